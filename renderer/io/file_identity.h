#pragma once
// Which file a path names, compared by what the kernel knows rather than by
// spelling: "a.obj", "./sub/../a.obj", a hard link and a symbolic link to it
// are one file. Used to keep a run from writing over a file it reads.

#include <sys/stat.h>
#include <sys/types.h>

#include <cstddef>
#include <optional>
#include <string>

namespace raylab {

/// \brief The identity of a file that exists (its device and inode), or of a
/// name not yet created (its directory's device and inode plus the name).
struct FileKey {
    dev_t dev = 0;
    ino_t ino = 0;
    std::string newName;  ///< empty for an existing file

    bool operator==(const FileKey& o) const {
        return dev == o.dev && ino == o.ino && newName == o.newName;
    }
    bool operator!=(const FileKey& o) const { return !(*this == o); }
};

struct FileKeyHash {
    size_t operator()(const FileKey& k) const;
};

/// The key of an existing file from its stat data (e.g. fstat of an open descriptor).
FileKey fileKeyOf(const struct stat& st);

/// The key of `path` with symbolic links followed: the file's own identity
/// when it exists, else its directory's plus the last name component.
/// nullopt when neither exists (a missing directory: nothing can be written there).
std::optional<FileKey> fileKeyOfPath(const std::string& path);

}  // namespace raylab
