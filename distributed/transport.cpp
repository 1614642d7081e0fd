#include "distributed/transport.h"

#include <algorithm>
#include <chrono>
#include <iterator>
#include <stdexcept>
#include <thread>

#include "distributed/config.h"
#include "renderer/timing.h"

namespace raylab {

namespace {

void check(int rc, const std::string& what) {
    if (rc == MPI_SUCCESS) return;
    char text[MPI_MAX_ERROR_STRING] = {};
    int len = 0;
    MPI_Error_string(rc, text, &len);
    throw std::runtime_error("MPI: " + what + ": " + std::string(text, size_t(len)));
}

}  // namespace

Transport::~Transport() {
    for (Outgoing& o : m_out) new std::vector<unsigned char>(std::move(o.bytes));
}

void Transport::post(int dest, int tag, std::vector<unsigned char> bytes) {
    m_out.push_back({MPI_REQUEST_NULL, std::move(bytes)});
    Outgoing& o = m_out.back();
    check(MPI_Isend(o.bytes.data(), int(o.bytes.size()), MPI_BYTE, dest, tag, MPI_COMM_WORLD,
                    &o.request),
          "send to rank " + std::to_string(dest));
}

void Transport::progress() {
    for (auto it = m_out.begin(); it != m_out.end();) {
        int flag = 0;
        check(MPI_Test(&it->request, &flag, MPI_STATUS_IGNORE), "send");
        it = flag ? m_out.erase(it) : std::next(it);
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
    int flag = 0;
    MPI_Status st;
    check(MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st),
          "probe rank " + std::to_string(source));
    if (!flag) return false;
    tag = st.MPI_TAG;
    check(MPI_Get_count(&st, MPI_BYTE, &bytes), "message size");
    return true;
}

std::vector<unsigned char> Transport::receive(int source, int tag, int bytes) {
    std::vector<unsigned char> data(size_t(std::max(0, bytes)));
    check(MPI_Recv(data.data(), bytes, MPI_BYTE, source, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
          "receive from rank " + std::to_string(source));
    return data;
}

}  // namespace raylab
