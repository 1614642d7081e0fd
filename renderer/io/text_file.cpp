#include "renderer/io/text_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "renderer/cancel.h"
#include "renderer/huge_pages.h"
#include "renderer/io/errors.h"
#include "renderer/io/input_files.h"

namespace raylab {

std::string readTextFile(const std::string& path, size_t maxBytes) {
    // O_NONBLOCK: opening a FIFO with no writer would otherwise wait for ever
    // (and not even SIGINT ends an open(2) blocked there). The file is refused
    // below unless it is a regular one, so the flag never affects a read.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0)
        throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) throw InputError(path, 0, "cannot open: is a directory");
    // A device (/dev/zero, /dev/urandom), FIFO or socket has no end that can be
    // trusted: reading it would take unbounded time and memory.
    if (!S_ISREG(st.st_mode))
        throw InputError(path, 0, "cannot open: not a regular file (a device, FIFO or socket)");
    const auto tooLarge = [&](double bytes) {
        const auto mib = [](double b) { return std::to_string(int64_t(b / (1 << 20))); };
        return InputError(path, 0, "file is " + mib(bytes) + " MiB, larger than the " +
                                       mib(double(maxBytes)) + " MiB a scene file may have");
    };
    if (uint64_t(st.st_size) > maxBytes) throw tooLarge(double(st.st_size));
    // Recorded before reading: an output must never name a file the run reads.
    recordInputFile(path, st);

    std::string text;
    text.reserve(size_t(st.st_size));
    adviseHugePages(text.data(), text.capacity());  // a 60 MB OBJ: far fewer page faults
    char buffer[1 << 16];
    while (true) {
        throwIfCancelled();  // a 1 GiB file on a slow disk is a phase of its own
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n == 0) break;
        if (n < 0) {
            if (errno == EINTR) continue;
            throw InputError(path, 0, std::string("read error: ") + std::strerror(errno));
        }
        // A file that grows while it is read (or reports size 0, as /proc
        // files do) is held to the same limit.
        if (text.size() + size_t(n) > maxBytes) throw tooLarge(double(text.size() + size_t(n)));
        text.append(buffer, size_t(n));
    }
    recordInputContent(st, text);  // what was read, for MPI ranks to compare
    return text;
}

std::pair<int, std::string> findNonText(std::string_view text, const std::string& format) {
    const auto byte = [&](size_t i) { return static_cast<unsigned char>(text[i]); };
    if (text.size() >= 2 &&
        ((byte(0) == 0xFF && byte(1) == 0xFE) || (byte(0) == 0xFE && byte(1) == 0xFF)))
        return {1, "file starts with a UTF-16 byte-order mark; " + format +
                       " must be ASCII or UTF-8 text"};
    const size_t nul = text.find('\0');
    if (nul == std::string_view::npos) return {0, ""};
    int line = 1;
    for (size_t i = 0; i < nul; ++i)
        if (text[i] == '\n') ++line;
    return {line, "NUL byte (binary data or a UTF-16 file); " + format +
                      " must be ASCII or UTF-8 text"};
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
