#include "distributed/transport.h"

#include <algorithm>
#include <chrono>
#include <iterator>
#include <stdexcept>
#include <thread>

#include "distributed/config.h"
#include "distributed/mpi_module_loader.h"
#include "renderer/timing.h"

namespace raylab {

namespace {

/// Throws the failure of the MPI call `what` with MPI's own `text`.
[[noreturn]] void fail(const std::string& what, const std::string& text) {
    throw std::runtime_error("MPI: " + what + ": " + text);
}

}  // namespace

Transport::Transport() : m_mpi(mpiModule()) {}

Transport::~Transport() {
    for (Outgoing& o : m_out) new std::vector<unsigned char>(std::move(o.bytes));
}

void Transport::post(int dest, int tag, std::vector<unsigned char> bytes) {
    m_out.push_back({nullptr, std::move(bytes)});
    Outgoing& o = m_out.back();
    std::string error;
    o.send = m_mpi.send(dest, tag, o.bytes.data(), int(o.bytes.size()), error);
    if (!o.send) {
        m_out.pop_back();
        fail("send to rank " + std::to_string(dest), error);
    }
}

void Transport::progress() {
    for (auto it = m_out.begin(); it != m_out.end();) {
        bool delivered = false;
        std::string error;
        if (!it->send->test(delivered, error)) fail("send", error);
        it = delivered ? m_out.erase(it) : std::next(it);
    }
}

bool Transport::flush(double timeout) {
    const auto t0 = std::chrono::steady_clock::now();
    for (;;) {
        progress();
        if (m_out.empty()) return true;
        if (secondsSince(t0) > timeout) return false;
        std::this_thread::sleep_for(kPollInterval);
    }
}

bool Transport::probe(int source, int& tag, int& bytes) {
    bool found = false;
    std::string error;
    if (!m_mpi.probe(source, found, tag, bytes, error))
        fail("probe rank " + std::to_string(source), error);
    return found;
}

std::vector<unsigned char> Transport::receive(int source, int tag, int bytes) {
    std::vector<unsigned char> data(size_t(std::max(0, bytes)));
    std::string error;
    if (!m_mpi.receive(source, tag, data.data(), bytes, error))
        fail("receive from rank " + std::to_string(source), error);
    return data;
}

}  // namespace raylab
