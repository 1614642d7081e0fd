#include "renderer/io/loading_file.h"

#include <exception>
#include <vector>

namespace raylab {

namespace {

thread_local std::vector<std::string> t_stack;
thread_local std::string t_innermost;

}  // namespace

LoadingFile::LoadingFile(const std::string& path) : m_exceptions(std::uncaught_exceptions()) {
    t_stack.push_back(path);
    t_innermost = path;
}

LoadingFile::~LoadingFile() {
    t_stack.pop_back();
    // Left normally: the enclosing file is being loaded again. Left by an
    // exception: this file stays named until the next load.
    if (std::uncaught_exceptions() == m_exceptions)
        t_innermost = t_stack.empty() ? std::string() : t_stack.back();
}

std::string fileBeingLoaded() { return t_innermost; }

}  // namespace raylab
