// Distributed frames against single-process frames. These cases run only
// when test_distributed itself is launched by mpirun (tests/distributed/
// mpi_tests.cmake: `mpirun -np 2 test_distributed --test-case=mpi:*`); every
// rank runs the same cases in the same order, and rank 0 compares.

#include <doctest/doctest.h>

#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "distributed_test_helpers.h"
#include "distributed/mpi_module_loader.h"
#include "distributed/mpi_render.h"
#include "distributed/mpi_session.h"
#include "renderer/camera_path.h"

using namespace raylab;

namespace {

/// One session for the whole test run: MPI can be initialised only once.
const MpiSession& session() {
    static const MpiSession s;
    return s;
}

const auto kUnderMpirun = doctest::skip(!launchedUnderMpirun());

/// Renders across the ranks; rank 0 also renders in one process and checks
/// that the film and every counter are identical and the loads add up.
void checkAgainstOneProcess(const test::PreparedScene& p, const std::string& what,
                            DistributedReport* reportOut = nullptr) {
    const MpiSession& mpi = session();
    REQUIRE(mpi.active());
    DistributedReport report;
    double lastProgress = -1;
    const RenderResult d = renderDistributed(mpi, p.scene, *p.accel, p.options, p.effects,
                                             [&](double f) { lastProgress = f; }, nullptr,
                                             &report);
    CHECK_FALSE(d.cancelled);
    if (!mpi.isRoot()) {
        CHECK(d.film.rgba.empty());  // only rank 0 holds the frame
        return;
    }
    const RenderResult s = render(p.scene, *p.accel, p.options, p.effects);
    INFO(what);
    CHECK(test::filmDifference(d.film, s.film) == "");
    CHECK(test::sameCounters(d.rays, s.rays));
    CHECK(d.nonFiniteSamples == s.nonFiniteSamples);
    CHECK(lastProgress == 1.0);
    REQUIRE(report.ranks == mpi.size());
    REQUIRE(report.loads.size() == size_t(mpi.size()));
    uint64_t items = 0, rays = 0;
    for (const RankLoad& l : report.loads) {
        items += l.items;
        rays += l.rays;
    }
    CHECK(items == uint64_t(report.items));
    CHECK(rays == s.rays.total());  // per-rank ray counts add up to one process's
    MESSAGE(what << "\n" << formatLoadReport(report));
    if (reportOut) *reportOut = report;
}

RenderOverrides small(int w, int h, int spp) {
    RenderOverrides o;
    o.width = w;
    o.height = h;
    o.spp = spp;
    o.threads = 1;  // two ranks on a shared two-core machine
    return o;
}

std::string demoPath() { return std::string(RAYLAB_SOURCE_DIR) + "/scenes/demo.json"; }

/// An SPD scene: ../shared's sphereflake of 91 spheres when present, else a
/// small NFF scene with a mirror, a glass sphere and a floor written here.
std::string spdScene() {
    const std::string shared = std::string(RAYLAB_SHARED_DIR) + "/scenes/spd/balls_s2.nff";
    if (std::filesystem::exists(shared)) return shared;
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("raylab_mpi_spd_" + std::to_string(long(getpid())) + ".nff"))
                                 .string();
    std::ofstream(path) << "v\nfrom 0 1 -6\nat 0 0.5 0\nup 0 1 0\nangle 40\nhither 0.01\n"
                           "resolution 64 64\nb 0.1 0.2 0.3\nl 3 5 -4\nl -4 6 -2\n"
                           "f 0.9 0.2 0.2 0.6 0.4 20 0 1\ns -1 0.5 0 0.5\n"
                           "f 0.8 0.8 0.9 0.1 0.6 100 0.8 1.5\ns 0.8 0.6 0.2 0.6\n"
                           "f 0.8 0.8 0.8 0.8 0.3 10 0 1\n"
                           "p 4\n-5 0 5\n5 0 5\n5 0 -5\n-5 0 -5\n";
    return path;
}

}  // namespace

TEST_CASE("mpi: the session loaded the MPI module" * kUnderMpirun) {
    REQUIRE(session().active());
    CHECK(mpiModuleLoaded());
    CHECK(session().size() >= 2);
}

TEST_CASE("mpi: demo scene tiles are bit-identical to one process" * kUnderMpirun) {
    const auto p = test::prepare(demoPath(), small(96, 64, 2));
    checkAgainstOneProcess(*p, "demo 96x64, 2 spp");
}

TEST_CASE("mpi: with rank 0 only serving, every item comes from the others" * kUnderMpirun) {
    setenv("RAYLAB_MPI_ROOT_RENDERS", "0", 1);
    const auto p = test::prepare(demoPath(), small(64, 48, 1));
    DistributedReport report;
    checkAgainstOneProcess(*p, "demo 64x48, rank 0 serving only", &report);
    unsetenv("RAYLAB_MPI_ROOT_RENDERS");
    if (session().isRoot()) {
        CHECK(report.loads[0].items == 0);
        CHECK(report.loads[0].rays == 0);
        uint64_t others = 0;
        for (size_t r = 1; r < report.loads.size(); ++r) others += report.loads[r].items;
        CHECK(others == 12);  // 64x48 pixels = 4x3 tiles
    }
}

TEST_CASE("mpi: SPD corner rows are bit-identical to one process" * kUnderMpirun) {
    RenderOverrides o = small(64, 64, 1);
    o.spd = true;
    const auto p = test::prepare(spdScene(), o);
    REQUIRE(p->options.spd);
    checkAgainstOneProcess(*p, "SPD 64x64");
}

TEST_CASE("mpi: supersampling (n-rooks spp 3, adaptive) is bit-identical" * kUnderMpirun) {
    RenderOverrides o = small(48, 40, 3);
    const auto jittered = test::prepare(demoPath(), o);
    checkAgainstOneProcess(*jittered, "demo 48x40, 3 spp jittered");
    o.spp = 1;
    o.adaptiveThreshold = 0.05;
    const auto adaptive = test::prepare(demoPath(), o);
    checkAgainstOneProcess(*adaptive, "demo 48x40, adaptive 0.05");
}

TEST_CASE("mpi: a cancel on rank 0 stops every rank" * kUnderMpirun) {
    const auto p = test::prepare(demoPath(), small(160, 120, 4));
    std::atomic<bool> cancel{false};
    // Rank 0 cancels at its first progress report: every rank returns cancelled.
    const RenderResult r = renderDistributed(session(), p->scene, *p->accel, p->options,
                                             p->effects, [&](double) { cancel = true; },
                                             &cancel);
    CHECK(r.cancelled);
    // Later frames still work (the next test case renders one).
}

TEST_CASE("mpi: a cancel on another rank stops every rank" * kUnderMpirun) {
    const auto p = test::prepare(demoPath(), small(160, 120, 4));
    std::atomic<bool> cancel{!session().isRoot()};  // the workers are interrupted at once
    const RenderResult r =
        renderDistributed(session(), p->scene, *p->accel, p->options, p->effects, {}, &cancel);
    CHECK(r.cancelled);
    // And the frame after a cancelled one is complete and identical again.
    const auto q = test::prepare(demoPath(), small(48, 32, 1));
    checkAgainstOneProcess(*q, "demo 48x32 after two cancelled frames");
}

TEST_CASE("mpi: a camera-path sequence, frame after frame" * kUnderMpirun) {
    auto p = test::prepare(demoPath(), small(48, 32, 1));
    CameraKeyframe a, b;
    a.frame = 1;
    a.eye = Vec3(0, 2.4, 8);
    a.lookAt = Vec3(0, 0.9, 0);
    a.fov = 40;
    b = a;
    b.frame = 3;
    b.eye = Vec3(6, 3, 5);
    const CameraPath path({a, b}, CameraPath::Interpolation::CatmullRom);
    for (int frame = 1; frame <= 3; ++frame) {
        p->scene.camera = path.cameraAt(frame);
        checkAgainstOneProcess(*p, "sequence frame " + std::to_string(frame));
    }
}
