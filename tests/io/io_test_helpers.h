#pragma once
// Shared by the io tests: a scratch directory, file writing and error capture.

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "renderer/io/errors.h"

namespace raylab::test {

/// A scratch directory per test case, removed at the end of the case.
class IoTempDir {
public:
    IoTempDir() {
        static std::atomic<int> counter{0};
        m_path = std::filesystem::temp_directory_path() /
                 ("raylab_test_io_" + std::to_string(long(::getpid())) + "_" +
                  std::to_string(counter++));
        std::filesystem::remove_all(m_path);
        std::filesystem::create_directories(m_path);
    }
    ~IoTempDir() {
        std::error_code ec;
        std::filesystem::remove_all(m_path, ec);
    }
    IoTempDir(const IoTempDir&) = delete;
    IoTempDir& operator=(const IoTempDir&) = delete;

    /// Full path of `name` inside the directory.
    std::string file(const std::string& name) const { return (m_path / name).string(); }

    /// Writes `text` to `name` and returns its full path.
    std::string write(const std::string& name, const std::string& text) const {
        const std::string p = file(name);
        std::filesystem::create_directories(std::filesystem::path(p).parent_path());
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }

private:
    std::filesystem::path m_path;
};

/// What an InputError said; line -1 when nothing was thrown.
struct Failure {
    std::string file;
    int line = -1;
    std::string message;
    std::string located;
};

inline Failure failureOf(const std::function<void()>& fn) {
    try {
        fn();
    } catch (const InputError& e) {
        return {e.file(), e.line(), e.what(), e.located()};
    }
    return {};
}

inline bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

}  // namespace raylab::test
