#pragma once
// A scratch directory for fuzz targets that must hand the loader a real file
// (the OBJ reader opens its MTL libraries by name). One per process, removed
// at exit.

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace raylab::fuzz {

class ScratchDir {
public:
    ScratchDir() {
        std::string tmpl =
            (std::filesystem::temp_directory_path() / "raylab-fuzz-XXXXXX").string();
        if (!::mkdtemp(tmpl.data())) {
            std::perror("raylab fuzz: mkdtemp");
            std::abort();
        }
        m_path = tmpl;
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(m_path, ec);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    std::string file(const std::string& name) const { return m_path + "/" + name; }

    /// Replaces `name` with exactly `size` bytes from `data`.
    std::string write(const std::string& name, const char* data, size_t size) const {
        const std::string p = file(name);
        std::FILE* f = std::fopen(p.c_str(), "wb");
        if (!f || std::fwrite(data, 1, size, f) != size || std::fclose(f) != 0) {
            std::perror("raylab fuzz: cannot write the scratch file");
            std::abort();
        }
        return p;
    }
    std::string write(const std::string& name, const std::string& text) const {
        return write(name, text.data(), text.size());
    }

private:
    std::string m_path;
};

/// The process-wide scratch directory (created on first use).
inline ScratchDir& scratch() {
    static ScratchDir dir;
    return dir;
}

}  // namespace raylab::fuzz
