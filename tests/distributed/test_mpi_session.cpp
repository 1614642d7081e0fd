// Without mpirun nothing distributed happens: no MPI loaded or initialised,
// and renderDistributed is exactly the single-process render.

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>
#include <thread>

#include "distributed_test_helpers.h"
#include "distributed/mpi_module_loader.h"
#include "distributed/mpi_render.h"
#include "distributed/mpi_session.h"
#include "support/run_command.h"

using namespace raylab;

namespace {

/// Sets or clears an environment variable for one scope.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : m_name(name) {
        if (const char* old = std::getenv(name)) m_old = old;
        if (value)
            setenv(name, value, 1);
        else
            unsetenv(name);
    }
    ~ScopedEnv() {
        if (m_old)
            setenv(m_name, m_old->c_str(), 1);
        else
            unsetenv(m_name);
    }

private:
    const char* m_name;
    std::optional<std::string> m_old;
};

}  // namespace

// Skipped under mpirun (the variables are set there); these are plain runs.
TEST_CASE("launchedUnderMpirun reads the launchers' variables" *
          doctest::skip(launchedUnderMpirun())) {
    const ScopedEnv a("OMPI_COMM_WORLD_SIZE", nullptr), b("PMI_SIZE", nullptr),
        c("PMIX_RANK", nullptr);
    CHECK_FALSE(launchedUnderMpirun());
    {
        const ScopedEnv open("OMPI_COMM_WORLD_SIZE", "4");
        CHECK(launchedUnderMpirun());
    }
    {
        const ScopedEnv hydra("PMI_SIZE", "2");
        CHECK(launchedUnderMpirun());
    }
    {
        const ScopedEnv pmix("PMIX_RANK", "0");
        CHECK(launchedUnderMpirun());
    }
    {
        const ScopedEnv empty("PMI_SIZE", "");
        CHECK_FALSE(launchedUnderMpirun());
    }
}

TEST_CASE("MpiSession: a plain run stays single-process" * doctest::skip(launchedUnderMpirun())) {
    const MpiSession mpi;
    CHECK_FALSE(mpi.active());
    CHECK(mpi.rank() == 0);
    CHECK(mpi.size() == 1);
    CHECK(mpi.isRoot());
    CHECK(mpi.ranksOnThisNode() == 1);
    CHECK_FALSE(mpi.host().empty());

    // Without a session renderDistributed is render(): same film, same counters.
    RenderOverrides o;
    o.width = 48;
    o.height = 32;
    o.threads = 2;
    const auto p = test::prepare(std::string(RAYLAB_SOURCE_DIR) + "/scenes/demo.json", o);
    DistributedReport report;
    report.ranks = 7;  // overwritten
    const RenderResult a = renderDistributed(mpi, p->scene, *p->accel, p->options, p->effects,
                                             {}, nullptr, &report);
    const RenderResult b = render(p->scene, *p->accel, p->options, p->effects);
    CHECK(test::filmDifference(a.film, b.film) == "");
    CHECK(test::sameCounters(a.rays, b.rays));
    CHECK(report.ranks == 1);
    CHECK(report.loads.empty());
    CHECK(formatLoadReport(report).empty());
    // Open MPI stays out of this process (distributed/mpi_module.h).
    CHECK_FALSE(mpiModuleLoaded());
    const std::string maps = test::readFile("/proc/self/maps");
    REQUIRE(maps.find("libembree3") != std::string::npos);  // the listing is there
    CHECK(maps.find("libmpi") == std::string::npos);
    CHECK(maps.find("libopen-pal") == std::string::npos);
}

TEST_CASE("the raylab executable names no MPI library: Open MPI is its module's") {
    // ld.so lists what it would load (as ldd does) and runs nothing.
    const test::CommandResult r =
        test::runCommand("LD_TRACE_LOADED_OBJECTS=1 '" + std::string(RAYLAB_BINARY) + "'");
    REQUIRE(r.exitCode == 0);
    REQUIRE(r.out.find("libembree3") != std::string::npos);  // the listing is there
    CHECK_MESSAGE(r.out.find("libmpi") == std::string::npos, r.out);
    CHECK_MESSAGE(r.out.find("libopen-pal") == std::string::npos, r.out);
    CHECK_MESSAGE(r.out.find("libhwloc") == std::string::npos, r.out);
}

TEST_CASE("threadsPerRank: explicit threads win, else all cores for a lone rank" *
          doctest::skip(launchedUnderMpirun())) {
    const MpiSession mpi;
    RenderOptions o;
    o.threads = 3;
    CHECK(threadsPerRank(mpi, o) == 3);
    o.threads = 0;
    CHECK(threadsPerRank(mpi, o) == std::max(1, int(std::thread::hardware_concurrency())));
}

TEST_CASE("formatLoadReport: one line per rank") {
    DistributedReport r;
    r.ranks = 2;
    r.items = 300;
    r.seconds = 1.5;
    RankLoad a;
    a.rank = 0;
    a.host = "alpha";
    a.threads = 1;
    a.items = 100;
    a.chunks = 10;
    a.busySeconds = 1.25;
    a.cpuSeconds = 1.125;
    a.finishSeconds = 1.5;
    a.rays = 2500000;
    RankLoad b = a;
    b.rank = 1;
    b.host = "beta";
    b.threads = 2;
    b.items = 200;
    b.bytesSent = 3 * 1024 * 1024;
    r.loads = {a, b};
    CHECK(formatLoadReport(r) ==
          "  ranks:    2 ranks, 300 tiles, 3.0 MiB gathered in 1.500 s\n"
          "    rank 0 (alpha, 1 thread): 100 items (33.3%) in 10 chunks, busy 1.250 s (cpu 1.125 "
          "s), done at 1.500 s, 2.50 Mrays\n"
          "    rank 1 (beta, 2 threads): 200 items (66.7%) in 10 chunks, busy 1.250 s (cpu 1.125 "
          "s), done at 1.500 s, 2.50 Mrays\n");
}
