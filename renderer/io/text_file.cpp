#include "renderer/io/text_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "renderer/io/errors.h"

namespace raylab {

std::string readTextFile(const std::string& path) {
    // stat first: fopen succeeds on a directory on Linux and only the read fails,
    // with a less helpful message.
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) throw InputError(path, 0, "cannot open: is a directory");

    std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));

    std::string text;
    char buffer[1 << 16];
    size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) text.append(buffer, n);
    if (std::ferror(file.get()))
        throw InputError(path, 0, std::string("read error: ") + std::strerror(errno));
    return text;
}

std::string directoryOf(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

std::string resolveRelativeTo(const std::string& base, const std::string& relative) {
    if (!relative.empty() && relative[0] == '/') return relative;
    return directoryOf(base) + relative;
}

std::string lowerExtension(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    const size_t nameStart = slash == std::string::npos ? 0 : slash + 1;
    const size_t dot = path.find_last_of('.');
    // A leading dot ("/x/.hidden") names a file, it is not an extension.
    if (dot == std::string::npos || dot <= nameStart) return "";
    std::string ext = path.substr(dot);
    for (char& c : ext)
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    return ext;
}

}  // namespace raylab
