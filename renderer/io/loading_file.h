#pragma once
// Which file the scene readers are turning into a scene right now, for
// errors that carry no file of their own: a std::bad_alloc thrown inside a
// parser (tinyobjloader under `ulimit -v`) would otherwise reach the user as
// a bare "out of memory".

#include <string>

namespace raylab {

/// \brief Marks `path` as being loaded on this thread for the scope's life;
/// scopes nest (a JSON scene, then a mesh it names).
class LoadingFile {
public:
    explicit LoadingFile(const std::string& path);
    ~LoadingFile();
    LoadingFile(const LoadingFile&) = delete;
    LoadingFile& operator=(const LoadingFile&) = delete;

private:
    int m_exceptions;  ///< std::uncaught_exceptions() when the scope began
};

/// The innermost file being loaded on this thread, "" when none. A scope left
/// by an exception keeps its name here, so that the handler which catches the
/// exception can still name the file.
std::string fileBeingLoaded();

}  // namespace raylab
