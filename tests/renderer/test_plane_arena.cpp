// A film's planes share one mapping (plane_arena.h): every plane lies in its
// film's arena, back to back, the arena sized exactly for them; containers
// still behave as with std::allocator (copies, moves, growth past the arena).

#include <doctest/doctest.h>

#include <cstdint>
#include <memory>
#include <tuple>
#include <utility>
#include <vector>

#include "renderer/film.h"
#include "renderer/plane_arena.h"

using namespace raylab;

TEST_CASE("plane arena: 64-byte slots front to back, nothing once full") {
    CHECK(PlaneArena::slot(1) == 64);
    CHECK(PlaneArena::slot(64) == 64);
    CHECK(PlaneArena::slot(65) == 128);
    PlaneArena arena(3 * 64);
    auto* a = static_cast<unsigned char*>(arena.take(10));
    auto* b = static_cast<unsigned char*>(arena.take(64));
    REQUIRE(a != nullptr);
    REQUIRE(b == a + 64);
    CHECK(arena.take(65) == nullptr);  // 64 bytes left
    auto* c = static_cast<unsigned char*>(arena.take(1));
    CHECK(c == a + 128);
    CHECK(arena.take(1) == nullptr);
    CHECK(arena.used() == arena.size());
    CHECK(arena.owns(a));
    CHECK(arena.owns(c + 63));
    CHECK_FALSE(arena.owns(c + 64));
}

TEST_CASE("film: every plane in one arena, sized for exactly them, blank values as before") {
    for (const auto& entry : {std::tuple{512, 512, 4}, std::tuple{640, 480, 6},
                              std::tuple{3, 2, 1}}) {
        // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
        const auto& w = std::get<0>(entry);
        const auto& h = std::get<1>(entry);
        const auto& ranks = std::get<2>(entry);
        CAPTURE(w);
        const Film film(w, h, 0, 0, w, h, ranks);
        const size_t n = size_t(w) * size_t(h);
        const std::shared_ptr<PlaneArena> arena = film.rgba.get_allocator().arena();
        REQUIRE(arena.get() != nullptr);
        const size_t floats = n * sizeof(float);
        CHECK(arena->size() == PlaneArena::slot(4 * floats) + 3 * PlaneArena::slot(floats) +
                                   2 * PlaneArena::slot(3 * floats) +
                                   PlaneArena::slot(n * size_t(ranks) * sizeof(MatteEntry)));
        CHECK(arena->used() == arena->size());
        for (const FilmPlane* p : {&film.rgba, &film.z, &film.distance, &film.normal, &film.albedo,
                                   &film.objectId})
            CHECK(arena->owns(p->data()));
        CHECK(arena->owns(film.mattes.data()));
        // Back to back in the order the constructor takes them.
        CHECK(reinterpret_cast<const unsigned char*>(film.z.data()) ==
              reinterpret_cast<const unsigned char*>(film.rgba.data()) + PlaneArena::slot(4 * floats));
        CHECK(film.rgba.size() == 4 * n);
        CHECK(film.mattes.size() == n * size_t(ranks));
        CHECK(film.rgba[4 * n - 1] == 0.f);
        CHECK(film.z[n - 1] == kNoHitDepth);
        CHECK(film.distance[0] == kNoHitDepth);
        CHECK(film.objectId[n - 1] == -1.f);
        CHECK(film.mattes[n * size_t(ranks) - 1].object == -1);
    }
}

TEST_CASE("film without AOVs: RGBA alone, the arena sized for it") {
    const Film film(64, 32, 0, 0, 64, 32, 4, /*aovs=*/false);
    const size_t n = 64 * 32;
    CHECK(film.rgba.size() == 4 * n);
    CHECK(film.rgba[4 * n - 1] == 0.f);
    for (const FilmPlane* p : {&film.z, &film.distance, &film.normal, &film.albedo, &film.objectId})
        CHECK(p->empty());
    CHECK(film.mattes.empty());
    // 32 KiB of the 168 KiB the same film takes with its layers (84 bytes per pixel).
    CHECK(film.rgba.get_allocator().arena()->size() == PlaneArena::slot(4 * n * sizeof(float)));
    CHECK(Film(64, 32, 0, 0, 64, 32, 4).rgba.get_allocator().arena()->size() == n * 84);
}

TEST_CASE("film planes: copies own their memory, moves keep the arena alive, growth falls back") {
    FilmPlane copy;
    FilmPlane moved;
    std::weak_ptr<PlaneArena> arena;
    {
        Film film(64, 64, 0, 0, 64, 64, 2);
        arena = film.rgba.get_allocator().arena();
        film.z[5] = 3.f;
        copy = film.z;  // copy-assignment: copy's own (default) allocator
        const FilmPlane constructed(film.normal);
        CHECK(constructed.get_allocator().arena().get() == nullptr);
        CHECK(constructed == film.normal);
        moved = std::move(film.distance);  // takes the buffer and the arena with it
        CHECK(moved.get_allocator().arena().get() == film.rgba.get_allocator().arena().get());
        film.rgba.resize(film.rgba.size() * 2, 1.f);  // no room left in the arena
        CHECK_FALSE(film.rgba.get_allocator().arena()->owns(film.rgba.data()));
        CHECK(film.rgba.back() == 1.f);
        CHECK(film.rgba.front() == 0.f);
    }
    // The film is gone; the moved plane still holds the arena and its values.
    REQUIRE(moved.get_allocator().arena().get() != nullptr);
    CHECK_FALSE(arena.expired());
    CHECK(moved.size() == 64 * 64);
    CHECK(moved[64 * 64 - 1] == kNoHitDepth);
    CHECK(copy.get_allocator().arena().get() == nullptr);
    CHECK(copy[5] == 3.f);
    CHECK(copy[6] == kNoHitDepth);
    moved = FilmPlane();  // the last plane from the arena lets go of it: unmapped
    CHECK(arena.expired());
}
