#include "renderer/io/input_files.h"

#include "renderer/file_content_hash.h"

namespace raylab {

namespace {

std::mutex g_logsMutex;       // guards g_current against logs opening and closing
InputFileLog* g_current = nullptr;

}  // namespace

InputFileLog::InputFileLog() {
    std::lock_guard<std::mutex> lock(g_logsMutex);
    m_outer = g_current;
    g_current = this;
}

InputFileLog::~InputFileLog() {
    std::lock_guard<std::mutex> lock(g_logsMutex);
    g_current = m_outer;
}

std::vector<InputFile> InputFileLog::files() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_files;
}

void InputFileLog::add(const std::string& path, const FileKey& key) {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_index.emplace(key, m_files.size()).second) m_files.push_back({path, key});
}

void InputFileLog::addContent(const FileKey& key, uint64_t bytes, uint64_t contentHash) {
    std::lock_guard<std::mutex> lock(m_mutex);
    const auto it = m_index.find(key);
    if (it == m_index.end()) return;
    m_files[it->second].bytes = bytes;
    m_files[it->second].contentHash = contentHash;
}

void recordInputFile(const std::string& path, const struct stat& st) {
    std::lock_guard<std::mutex> lock(g_logsMutex);
    if (g_current) g_current->add(path, fileKeyOf(st));
}

void recordInputContent(const struct stat& st, std::string_view bytes) {
    const uint64_t hash = fileContentHash(bytes);  // a pass over the file, outside the lock
    std::lock_guard<std::mutex> lock(g_logsMutex);
    if (g_current) g_current->addContent(fileKeyOf(st), bytes.size(), hash);
}

void recordInputFile(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) recordInputFile(path, st);
}

}  // namespace raylab
