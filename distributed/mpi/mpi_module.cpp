// raylab-mpi.so: the MPI calls of raylab behind distributed/mpi_module.h,
// loaded by MpiSession only under an MPI launcher. Nothing throws out of
// here: failures are returned as text.

#include <memory>
#include <new>
#include <string>

#include "distributed/mpi/mpi_c_api.h"
#include "distributed/mpi_module.h"

namespace raylab::mpi_module {

namespace {

/// MPI's text for the error code `rc`.
std::string errorText(int rc) {
    char text[MPI_MAX_ERROR_STRING] = {};
    int len = 0;
    if (MPI_Error_string(rc, text, &len) != MPI_SUCCESS) return "MPI error " + std::to_string(rc);
    return std::string(text, size_t(len));
}

bool start(World& world, std::string& error) {
    int initialised = 0, finalised = 0;
    MPI_Initialized(&initialised);
    MPI_Finalized(&finalised);
    if (initialised || finalised) {
        error = "MPI: only one MpiSession per process";
        return false;
    }
    int provided = 0;
    if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        error = "MPI: MPI_Init_thread failed";
        return false;
    }
    if (provided < MPI_THREAD_FUNNELED) {
        // Render threads coexist with MPI calls on the main thread; an MPI
        // that cannot promise that is unusable here.
        MPI_Finalize();
        error = "MPI: the library does not provide MPI_THREAD_FUNNELED";
        return false;
    }
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    MPI_Comm_rank(MPI_COMM_WORLD, &world.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &world.size);
    // Ranks on this machine share its cores: the default thread count divides them.
    MPI_Comm node;
    if (MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, world.rank, MPI_INFO_NULL,
                            &node) == MPI_SUCCESS) {
        MPI_Comm_size(node, &world.nodeRanks);
        MPI_Comm_free(&node);
    }
    return true;
}

void finish() { MPI_Finalize(); }

class MpiSend final : public Send {
public:
    bool test(bool& delivered, std::string& error) override {
        int flag = 0;
        const int rc = MPI_Test(&request, &flag, MPI_STATUS_IGNORE);
        if (rc != MPI_SUCCESS) {
            error = errorText(rc);
            return false;
        }
        delivered = flag != 0;
        return true;
    }
    MPI_Request request = MPI_REQUEST_NULL;
};

std::unique_ptr<Send> send(int dest, int tag, const unsigned char* bytes, int size,
                           std::string& error) {
    auto s = std::make_unique<MpiSend>();
    const int rc = MPI_Isend(bytes, size, MPI_BYTE, dest, tag, MPI_COMM_WORLD, &s->request);
    if (rc != MPI_SUCCESS) {
        error = errorText(rc);
        return nullptr;
    }
    return s;
}

bool probe(int source, bool& found, int& tag, int& size, std::string& error) {
    int flag = 0;
    MPI_Status st;
    int rc = MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
    found = flag != 0;
    if (rc == MPI_SUCCESS && found) {
        tag = st.MPI_TAG;
        rc = MPI_Get_count(&st, MPI_BYTE, &size);
    }
    if (rc == MPI_SUCCESS) return true;
    error = errorText(rc);
    return false;
}

bool receive(int source, int tag, unsigned char* bytes, int size, std::string& error) {
    const int rc =
        MPI_Recv(bytes, size, MPI_BYTE, source, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (rc == MPI_SUCCESS) return true;
    error = errorText(rc);
    return false;
}

const Api kApi{kVersion, &start, &finish, &send, &probe, &receive};

}  // namespace

}  // namespace raylab::mpi_module

extern "C" __attribute__((visibility("default"))) const raylab::mpi_module::Api*
raylab_mpi_module_v1() {
    return &raylab::mpi_module::kApi;
}
