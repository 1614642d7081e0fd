#pragma once
// The files a run reads. Every input goes through one of two hooks:
// readTextFile (scenes, meshes, MTL libraries, camera paths) records what it
// opened by the identity of the open descriptor, and a binary reader (a
// texture, say) calls recordInputFile before reading. The render command
// then refuses any output that is one of these files, and the ranks of an MPI
// job compare what they read (distributed/render_identity.h).

#include <sys/stat.h>

#include <cstdint>
#include <mutex>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "renderer/io/file_identity.h"

namespace raylab {

struct InputFile {
    std::string path;  ///< as it was opened
    FileKey key;
    /// What readTextFile read: its size and content hash (renderer/file_content_hash.h);
    /// both 0 for a file recorded by path only.
    uint64_t bytes = 0;
    uint64_t contentHash = 0;
};

/// \brief While alive, collects every input file read in this process (any
/// thread). Logs nest: only the innermost one records.
class InputFileLog {
public:
    InputFileLog();
    ~InputFileLog();
    InputFileLog(const InputFileLog&) = delete;
    InputFileLog& operator=(const InputFileLog&) = delete;

    /// Each file once (by identity), in the order first read.
    std::vector<InputFile> files() const;

    void add(const std::string& path, const FileKey& key);
    /// Size and content hash of what was read from the file `key` names (added before).
    void addContent(const FileKey& key, uint64_t bytes, uint64_t contentHash);

private:
    mutable std::mutex m_mutex;
    std::vector<InputFile> m_files;
    std::unordered_map<FileKey, size_t, FileKeyHash> m_index;  ///< into m_files
    InputFileLog* m_outer;
};

/// Records an input opened as a descriptor, from its fstat data (so the file
/// recorded is exactly the one read, whatever its path resolves to later).
void recordInputFile(const std::string& path, const struct stat& st);

/// Records the bytes read from an input recorded by recordInputFile(path, st).
void recordInputContent(const struct stat& st, std::string_view bytes);

/// Records an input by path (stat follows links); for readers that open files
/// themselves, called before they read. A path that cannot be stat'ed is not
/// recorded: the reader's own open will fail and report it.
void recordInputFile(const std::string& path);

}  // namespace raylab
