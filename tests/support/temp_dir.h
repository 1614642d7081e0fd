#pragma once
// The one scratch directory of the test suites and fuzz targets: a fresh
// directory (per test case, or per fuzzing process), removed with its contents
// when it goes out of scope, and reading back what a test or the raylab binary
// wrote there. Header-only, included as "support/temp_dir.h".

#include <stdlib.h>  // mkdtemp

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace raylab::test {

class TempDir {
public:
    /// A new directory under the system temp dir. mkdtemp makes the name
    /// unique across processes, so parallel ctest runs never share one.
    TempDir() {
        std::string name = (std::filesystem::temp_directory_path() / "raylab_test_XXXXXX").string();
        if (!::mkdtemp(name.data()))
            throw std::runtime_error("mkdtemp " + name + ": " + std::strerror(errno));
        m_path = name;
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(m_path, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return m_path; }
    /// Full path of `name` inside the directory.
    std::string file(const std::string& name) const { return (m_path / name).string(); }

    /// Writes exactly `bytes` to `name` (creating its folders); returns the full path.
    /// \throws std::runtime_error when the file cannot be written.
    std::string write(const std::string& name, const std::string& bytes) const {
        const std::string p = file(name);
        std::filesystem::create_directories(std::filesystem::path(p).parent_path());
        std::ofstream out(p, std::ios::binary);
        out << bytes;
        out.close();
        if (!out) throw std::runtime_error("cannot write the test file " + p);
        return p;
    }

    /// Names of the entries directly in the directory (files, folders, anything), sorted.
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(m_path))
            names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

    /// Paths, relative to the directory, of every regular file below it, sorted.
    std::vector<std::string> files() const {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::recursive_directory_iterator(m_path))
            if (e.is_regular_file())
                names.push_back(std::filesystem::relative(e.path(), m_path).string());
        std::sort(names.begin(), names.end());
        return names;
    }

private:
    std::filesystem::path m_path;
};

/// Whole contents of a file as bytes ("" when it cannot be opened).
inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace raylab::test
