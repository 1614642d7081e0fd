#pragma once
// Point-to-point MPI on MPI_COMM_WORLD (through the MPI module, mpi_module.h)
// with every call checked: errors return (MPI_ERRORS_RETURN) and become
// exceptions naming the call. Sends are non-blocking and kept until
// delivered, so neither side ever blocks on the other. Used only within an
// active MpiSession, which has loaded the module.

#include <list>
#include <memory>
#include <string>
#include <vector>

#include "distributed/mpi_module.h"

namespace raylab {

class Transport {
public:
    Transport();
    /// Leaks the buffers of undelivered sends (only on an error path, just
    /// before the process ends): they must outlive MPI's use of them.
    ~Transport();
    Transport(const Transport&) = delete;
    Transport& operator=(const Transport&) = delete;

    /// Sends `bytes` to rank `dest` without waiting.
    void post(int dest, int tag, std::vector<unsigned char> bytes);

    /// Lets MPI advance the pending sends; forgets the delivered ones.
    void progress();

    /// Waits up to `timeout` seconds for every pending send; false if some remain.
    bool flush(double timeout);

    /// A message from `source` waiting to be received: its tag and size.
    bool probe(int source, int& tag, int& bytes);

    /// Receives the message probe() announced.
    std::vector<unsigned char> receive(int source, int tag, int bytes);

private:
    struct Outgoing {
        std::unique_ptr<mpi_module::Send> send;
        std::vector<unsigned char> bytes;
    };
    const mpi_module::Api& m_mpi;
    std::list<Outgoing> m_out;  ///< std::list: buffers never move while MPI holds them
};

}  // namespace raylab
