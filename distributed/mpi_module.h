#pragma once
// The narrow interface between raylab and its MPI module (raylab-mpi.so,
// built from distributed/mpi/). Open MPI brings seven shared libraries
// (libmpi, libopen-rte, libopen-pal, hwloc, libevent, udev) whose loading
// and relocation every process paid at start-up, although only a launch
// under mpirun uses them. So the module is loaded with dlopen by MpiSession
// when an MPI launcher started the process (mpi_module_loader.h), and a
// plain `raylab render` or `raylab --help` starts without it.
//
// These are the only MPI calls raylab makes: the session's start and end and
// point-to-point byte messages on MPI_COMM_WORLD. Only standard types cross
// the boundary (raylab and the module are built together, by the same
// compiler), and nothing is thrown across it: failures come back as text.

#include <memory>
#include <string>

namespace raylab::mpi_module {

/// Bumped whenever anything below changes shape.
constexpr int kVersion = 1;
/// The module's one exported symbol: `extern "C" const Api* raylab_mpi_module_v1()`.
constexpr const char* kEntryPoint = "raylab_mpi_module_v1";

/// This process's place in MPI_COMM_WORLD.
struct World {
    int rank = 0;
    int size = 1;
    int nodeRanks = 1;  ///< ranks sharing this machine (MPI_COMM_TYPE_SHARED)
};

/// A non-blocking send on its way. The caller keeps the bytes alive and in
/// place until done() says delivered.
class Send {
public:
    virtual ~Send() = default;
    /// Lets MPI advance the send: `delivered` once it is; false (and `error`
    /// set to MPI's text) when MPI reports a failure.
    virtual bool test(bool& delivered, std::string& error) = 0;
};

struct Api {
    int version = kVersion;
    /// MPI_Init_thread with MPI_THREAD_FUNNELED, errors returned
    /// (MPI_ERRORS_RETURN) on MPI_COMM_WORLD, then its rank, size and the
    /// ranks on this machine. false (and `error` set, the whole sentence)
    /// when MPI cannot be started or was started before.
    bool (*start)(World& world, std::string& error) = nullptr;
    /// MPI_Finalize.
    void (*finish)() = nullptr;
    /// MPI_Isend of `size` bytes to rank `dest`; nullptr (and `error` set to
    /// MPI's text) when MPI refuses it.
    std::unique_ptr<Send> (*send)(int dest, int tag, const unsigned char* bytes, int size,
                                  std::string& error) = nullptr;
    /// MPI_Iprobe for any tag from `source`: `found`, and then the message's
    /// tag and size. false (and `error` set) when MPI reports a failure.
    bool (*probe)(int source, bool& found, int& tag, int& size, std::string& error) = nullptr;
    /// MPI_Recv of the message probe() announced into `bytes` (`size` of them).
    bool (*receive)(int source, int tag, unsigned char* bytes, int size,
                    std::string& error) = nullptr;
};

}  // namespace raylab::mpi_module
