#include "renderer/io/file_identity.h"

#include <functional>

#include "renderer/io/text_file.h"

namespace raylab {

size_t FileKeyHash::operator()(const FileKey& k) const {
    const size_t h = std::hash<unsigned long long>()((unsigned long long)k.dev * 0x9E3779B97F4A7C15ULL ^
                                                     (unsigned long long)k.ino);
    return k.newName.empty() ? h : h ^ (std::hash<std::string>()(k.newName) << 1);
}

FileKey fileKeyOf(const struct stat& st) { return FileKey{st.st_dev, st.st_ino, ""}; }

std::optional<FileKey> fileKeyOfPath(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) return fileKeyOf(st);
    // Not there (yet): the directory it would be created in, plus its name.
    std::string dir = directoryOf(path);
    std::string name = path.substr(dir.size());
    if (dir.empty()) dir = ".";
    if (name.empty() || name == "." || name == "..") return std::nullopt;
    if (::stat(dir.c_str(), &st) != 0) return std::nullopt;
    return FileKey{st.st_dev, st.st_ino, name};
}

}  // namespace raylab
