#include <doctest/doctest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "renderer/io/atomic_file.h"
#include "renderer/io/errors.h"
#include "support/temp_dir.h"

using namespace raylab;
using raylab::test::readFile;
using raylab::test::TempDir;

TEST_CASE("atomic file: string overload writes the bytes and leaves no temporary") {
    TempDir dir;
    const std::string target = dir.file("doc.json");
    writeFileAtomically(target, std::string("{\"a\": 1}\n\0x", 11));
    CHECK(readFile(target) == std::string("{\"a\": 1}\n\0x", 11));
    CHECK(dir.entries() == std::vector<std::string>{"doc.json"});
    CHECK(inFlightTempFileCount() == 0);

    // Replacing an existing file.
    writeFileAtomically(target, std::string("new"));
    CHECK(readFile(target) == "new");
    CHECK(dir.entries() == std::vector<std::string>{"doc.json"});
}

TEST_CASE("atomic file: the writer gets an empty registered temporary beside the target") {
    TempDir dir;
    const std::string target = dir.file("img.exr");
    std::string seen;
    writeFileAtomically(target, [&](const std::string& tmp) {
        seen = tmp;
        CHECK(std::filesystem::path(tmp).parent_path() == dir.path());
        CHECK(tmp.rfind(target + ".tmp.", 0) == 0);
        CHECK(std::filesystem::exists(tmp));
        CHECK(std::filesystem::file_size(tmp) == 0);
        CHECK_FALSE(std::filesystem::exists(target));  // not visible until complete
        CHECK(inFlightTempFileCount() == 1);
        std::ofstream(tmp, std::ios::binary) << "payload";
    });
    CHECK(readFile(target) == "payload");
    CHECK_FALSE(std::filesystem::exists(seen));
    CHECK(inFlightTempFileCount() == 0);
}

TEST_CASE("atomic file: a throwing writer leaves the target absent and no temporary") {
    TempDir dir;
    const std::string target = dir.file("out.png");
    try {
        writeFileAtomically(target, [](const std::string& tmp) {
            std::ofstream(tmp) << "half written";
            throw std::runtime_error("disk on fire");
        });
        FAIL("expected InputError");
    } catch (const InputError& e) {
        CHECK(e.file() == target);
        CHECK(e.line() == 0);
        CHECK(std::string(e.what()).find("disk on fire") != std::string::npos);
    }
    CHECK(dir.entries().empty());
    CHECK(inFlightTempFileCount() == 0);
}

TEST_CASE("atomic file: a failed write keeps the previous file intact") {
    TempDir dir;
    const std::string target = dir.file("out.exr");
    writeFileAtomically(target, std::string("old"));
    CHECK_THROWS_AS(writeFileAtomically(target,
                                        [](const std::string& tmp) {
                                            std::ofstream(tmp) << "partial";
                                            throw std::runtime_error("interrupted");
                                        }),
                    InputError);
    CHECK(readFile(target) == "old");
    CHECK(dir.entries() == std::vector<std::string>{"out.exr"});
}

TEST_CASE("atomic file: missing directory and unrenamable target are InputErrors") {
    TempDir dir;
    const std::string missing = dir.file("no/such/dir/out.exr");
    try {
        writeFileAtomically(missing, std::string("x"));
        FAIL("expected InputError");
    } catch (const InputError& e) {
        CHECK(e.file() == missing);
        CHECK(std::string(e.what()).find("No such file or directory") != std::string::npos);
    }
    CHECK(dir.entries().empty());

    // A non-empty directory cannot be replaced by rename(2): the temporary
    // must be cleaned up and the directory left alone.
    const std::string target = dir.file("occupied");
    std::filesystem::create_directories(target + "/child");
    CHECK_THROWS_AS(writeFileAtomically(target, std::string("x")), InputError);
    CHECK(dir.entries() == std::vector<std::string>{"occupied"});
    CHECK(std::filesystem::is_directory(target + "/child"));
    CHECK(inFlightTempFileCount() == 0);
}

TEST_CASE("atomic file: removeInFlightTempFiles deletes the temporary of a write in progress") {
    TempDir dir;
    const std::string target = dir.file("big.exr");
    std::string tmpSeen;
    // Simulates the SIGINT handler running while the image is being written:
    // the temporary disappears, so the final rename fails and nothing is left.
    CHECK_THROWS_AS(writeFileAtomically(target,
                                        [&](const std::string& tmp) {
                                            tmpSeen = tmp;
                                            std::ofstream(tmp) << "partial";
                                            removeInFlightTempFiles();
                                            CHECK_FALSE(std::filesystem::exists(tmp));
                                        }),
                    InputError);
    CHECK_FALSE(tmpSeen.empty());
    CHECK(dir.entries().empty());
    CHECK(inFlightTempFileCount() == 0);
}

TEST_CASE("atomic file: empty path is rejected") {
    CHECK_THROWS_AS(writeFileAtomically("", std::string("x")), InputError);
}

TEST_CASE("atomic file group: all files appear at commit, none before") {
    TempDir dir;
    AtomicFileGroup group;
    writeFileAtomically(dir.file("a.exr"), std::string("image"), &group);
    writeFileAtomically(dir.file("a.json"), std::string("stats"), &group);
    CHECK_FALSE(std::filesystem::exists(dir.file("a.exr")));
    CHECK_FALSE(std::filesystem::exists(dir.file("a.json")));
    CHECK(inFlightTempFileCount() == 2);
    group.commit();
    CHECK(readFile(dir.file("a.exr")) == "image");
    CHECK(readFile(dir.file("a.json")) == "stats");
    CHECK(dir.entries() == std::vector<std::string>{"a.exr", "a.json"});
    CHECK(inFlightTempFileCount() == 0);
}

TEST_CASE("atomic file group: a failed later write leaves every earlier target untouched") {
    TempDir dir;
    writeFileAtomically(dir.file("a.exr"), std::string("old image"));
    writeFileAtomically(dir.file("a.png"), std::string("old preview"));
    {
        AtomicFileGroup group;
        writeFileAtomically(dir.file("a.exr"), std::string("new image"), &group);
        writeFileAtomically(dir.file("a.png"), std::string("new preview"), &group);
        // The statistics cannot be written: the render command stops here and
        // the group goes out of scope without commit().
        CHECK_THROWS_AS(writeFileAtomically(dir.file("no/dir/a.json"), std::string("s"), &group),
                        InputError);
    }
    CHECK(readFile(dir.file("a.exr")) == "old image");
    CHECK(readFile(dir.file("a.png")) == "old preview");
    CHECK(dir.entries() == std::vector<std::string>{"a.exr", "a.png"});
    CHECK(inFlightTempFileCount() == 0);
}

TEST_CASE("atomic file group: a target that changed kind during the render stops the whole commit") {
    TempDir dir;
    writeFileAtomically(dir.file("third.txt"), std::string("old 3"));
    AtomicFileGroup group;
    writeFileAtomically(dir.file("first.txt"), std::string("1"), &group);
    writeFileAtomically(dir.file("second"), std::string("2"), &group);
    writeFileAtomically(dir.file("third.txt"), std::string("3"), &group);
    // Something else takes the second name meanwhile: rename(2) cannot
    // replace a non-empty directory, so nothing is renamed at all.
    std::filesystem::create_directories(dir.file("second/child"));
    try {
        group.commit();
        FAIL("expected InputError");
    } catch (const InputError& e) {
        CHECK(e.file() == dir.file("second"));
        CHECK(e.message().find("no longer a regular file") != std::string::npos);
    }
    CHECK(readFile(dir.file("third.txt")) == "old 3");
    CHECK(dir.entries() == std::vector<std::string>{"second", "third.txt"});
    CHECK(inFlightTempFileCount() == 0);
}

TEST_CASE("atomic file: a replaced file keeps its permission bits, a new one gets the umask's") {
    TempDir dir;
    const std::string target = dir.file("private.json");
    writeFileAtomically(target, std::string("old"));
    REQUIRE(::chmod(target.c_str(), 0600) == 0);
    writeFileAtomically(target, std::string("new"));
    struct stat st {};
    REQUIRE(::stat(target.c_str(), &st) == 0);
    CHECK((st.st_mode & 07777) == 0600);
    CHECK(readFile(target) == "new");
    REQUIRE(::chmod(target.c_str(), 0444) == 0);  // read-only: replaced all the same
    writeFileAtomically(target, std::string("newer"));
    REQUIRE(::stat(target.c_str(), &st) == 0);
    CHECK((st.st_mode & 07777) == 0444);
    CHECK(dir.entries() == std::vector<std::string>{"private.json"});  // no kept copy left
}

TEST_CASE("atomic file: a legal 255-byte output name works, temporaries stay within NAME_MAX") {
    TempDir dir;
    const std::string name = std::string(251, 'n') + ".exr";
    REQUIRE(name.size() == 255);
    const std::string target = dir.file(name);
    std::string seen;
    writeFileAtomically(target, [&](const std::string& tmp) {
        seen = tmp;
        std::ofstream(tmp) << "first";
    });
    CHECK(std::filesystem::path(seen).filename().string().size() <= 255);
    writeFileAtomically(target, std::string("second"));  // replacing: a kept copy beside it too
    CHECK(readFile(target) == "second");
    CHECK(dir.entries() == std::vector<std::string>{name});
    // A multi-byte UTF-8 name is never cut inside a character.
    std::string utf8;
    for (int i = 0; i < 75; ++i) utf8 += "\xC3\xA9";  // 'e' with acute, 150 bytes
    const std::string accented = dir.file(std::string(101, 'a') + utf8 + ".png");
    writeFileAtomically(accented, [&](const std::string& tmp) {
        const std::string base = std::filesystem::path(tmp).filename().string();
        const size_t stem = base.find(".tmp.");
        REQUIRE(stem != std::string::npos);
        CHECK(stem <= 200);
        CHECK((static_cast<unsigned char>(base[stem - 1]) & 0xC0) != 0xC0);  // not a lead byte cut off
        std::ofstream(tmp) << "x";
    });
    CHECK(readFile(accented) == "x");
}

TEST_CASE("atomic file: checkWritable refuses missing folders and directories, touches nothing") {
    TempDir dir;
    CHECK_NOTHROW(checkWritable(dir.file("new.exr")));
    CHECK(dir.entries().empty());
    writeFileAtomically(dir.file("old.exr"), std::string("keep"));
    CHECK_NOTHROW(checkWritable(dir.file("old.exr")));
    CHECK(readFile(dir.file("old.exr")) == "keep");
    CHECK_THROWS_AS(checkWritable(dir.file("no/such/dir/out.exr")), InputError);
    std::filesystem::create_directories(dir.file("folder.exr"));
    try {
        checkWritable(dir.file("folder.exr"));
        FAIL("expected InputError");
    } catch (const InputError& e) {
        CHECK(e.file() == dir.file("folder.exr"));
        CHECK(std::string(e.what()).find("directory") != std::string::npos);
    }
    CHECK(dir.entries() == std::vector<std::string>{"folder.exr", "old.exr"});
    CHECK(inFlightTempFileCount() == 0);
}

TEST_CASE("atomic file: a temporary left by a killed run does not block the next write") {
    TempDir dir;
    const std::string target = dir.file("out.exr");
    // Occupy the next few temporary names this process would choose, as a run
    // killed with the same pid would have left them.
    std::string probe;
    writeFileAtomically(target, [&](const std::string& tmp) { probe = tmp; });
    const std::string stem = probe.substr(0, probe.rfind('.') + 1);
    const unsigned long next = std::stoul(probe.substr(probe.rfind('.') + 1)) + 1;
    for (unsigned long k = next; k < next + 3; ++k)
        std::ofstream(stem + std::to_string(k)) << "stale";
    writeFileAtomically(target, std::string("fresh"));
    CHECK(readFile(target) == "fresh");
    CHECK(dir.entries().size() == 4);  // out.exr and the three stale files, untouched
    CHECK(inFlightTempFileCount() == 0);
}
