// releaseAtExit (apps/exit_keep.h): an object is destroyed on the spot unless
// main() said that the process ends after the command; then it is kept,
// reachable, until the process exits.

#include <doctest/doctest.h>

#include <memory>
#include <utility>

#include "apps/exit_keep.h"

using namespace raylab;

namespace {

struct Counted {
    int* destroyed;
    explicit Counted(int* d) : destroyed(d) {}
    Counted(Counted&& o) noexcept : destroyed(std::exchange(o.destroyed, nullptr)) {}
    ~Counted() {
        if (destroyed) ++*destroyed;
    }
};

}  // namespace

TEST_CASE("releaseAtExit: destroyed at once in-process, kept once the process ends after the command") {
    REQUIRE_FALSE(processEndsAfterCommand());  // a test binary never says so
    int destroyed = 0;
    releaseAtExit(Counted(&destroyed));
    CHECK(destroyed == 1);
    auto owned = std::make_unique<Counted>(&destroyed);
    releaseAtExit(std::move(owned));
    CHECK(owned == nullptr);
    CHECK(destroyed == 2);

    setProcessEndsAfterCommand();
    CHECK(processEndsAfterCommand());
    static int kept = 0;  // outlives the test: the kept objects refer to it at exit
    releaseAtExit(Counted(&kept));
    releaseAtExit(std::make_unique<Counted>(&kept));
    CHECK(kept == 0);
}
