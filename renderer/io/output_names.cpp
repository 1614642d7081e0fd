#include "renderer/io/output_names.h"

#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>
#include <unordered_map>

#include "renderer/io/atomic_file.h"
#include "renderer/io/errors.h"
#include "renderer/io/file_identity.h"
#include "renderer/io/text_file.h"

namespace raylab {

namespace {

/// Up to this many frames, each numbered name is looked up; beyond, the
/// output directory is scanned once (a sequence may have 10^7 frames).
constexpr int kListedFrames = 64;

std::string baseName(const std::string& path) { return path.substr(directoryOf(path).size()); }

bool allDigits(const std::string& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(),
                                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

/// The file names one output flag writes, all in one directory.
struct NameSet {
    const OutputFlag* out = nullptr;
    const OutputFrames* frames = nullptr;
    std::string dir;                ///< as written, with its '/' ("" = working directory)
    std::optional<FileKey> dirKey;  ///< nullopt: the directory does not exist
    std::vector<std::string> listed;
    bool pattern = false;  ///< frames too many to list: prefix DIGITS suffix
    std::string prefix, suffix;

    bool contains(const std::string& name) const {
        if (!pattern) return std::find(listed.begin(), listed.end(), name) != listed.end();
        if (name.size() <= prefix.size() + suffix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
            return false;
        const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
        if (!allDigits(digits) || digits.size() > 9) return false;
        const int frame = std::stoi(digits);
        return frame >= frames->first && frame <= frames->last &&
               baseName(frames->nameOf(out->path, frame)) == name;
    }
    /// Names that stand for the set when comparing two sets by name.
    std::vector<std::string> samples() const {
        if (!pattern) return listed;
        return {baseName(frames->nameOf(out->path, frames->first)),
                baseName(frames->nameOf(out->path, frames->last))};
    }
    std::string shown(const std::string& name) const { return dir + name; }
};

NameSet namesOf(const OutputFlag& out, const OutputFrames* frames) {
    NameSet set;
    set.out = &out;
    set.frames = frames;
    if (!frames) {
        set.dir = directoryOf(out.path);
        set.listed = {baseName(out.path)};
    } else {
        set.dir = directoryOf(frames->nameOf(out.path, frames->first));
        if (frames->last - frames->first < kListedFrames) {
            for (int f = frames->first; f <= frames->last; ++f)
                set.listed.push_back(baseName(frames->nameOf(out.path, f)));
        } else {
            // The parts two consecutive names share, less the digits of the number.
            const std::string a = baseName(frames->nameOf(out.path, frames->first));
            const std::string b = baseName(frames->nameOf(out.path, frames->first + 1));
            size_t p = 0, q = 0;
            while (p < a.size() && p < b.size() && a[p] == b[p]) ++p;
            while (q < a.size() - p && q < b.size() - p && a[a.size() - 1 - q] == b[b.size() - 1 - q]) ++q;
            while (p > 0 && std::isdigit(static_cast<unsigned char>(a[p - 1]))) --p;
            size_t s = a.size() - q;
            while (s < a.size() && std::isdigit(static_cast<unsigned char>(a[s]))) ++s;
            set.pattern = true;
            set.prefix = a.substr(0, p);
            set.suffix = a.substr(s);
            // A numbering this reading does not fit is listed in full instead.
            if (!set.contains(a) ||
                !set.contains(baseName(frames->nameOf(out.path, frames->last)))) {
                set.pattern = false;
                for (int f = frames->first; f <= frames->last; ++f)
                    set.listed.push_back(baseName(frames->nameOf(out.path, f)));
            }
        }
    }
    set.dirKey = fileKeyOfPath(set.dir.empty() ? "." : set.dir);
    if (set.dirKey && !set.dirKey->newName.empty()) set.dirKey.reset();  // not a directory yet
    return set;
}

bool sameDirectory(const NameSet& a, const NameSet& b) {
    if (a.dirKey && b.dirKey) return *a.dirKey == *b.dirKey;
    std::error_code ea, eb;
    const auto norm = [](const std::string& d, std::error_code& ec) {
        return std::filesystem::absolute(d.empty() ? "." : d, ec).lexically_normal();
    };
    return norm(a.dir, ea) == norm(b.dir, eb);
}

/// The names of `set` that exist now (listed names looked up, or the
/// directory scanned for the pattern).
std::vector<std::string> existingNames(const NameSet& set) {
    std::vector<std::string> found;
    if (!set.pattern) {
        for (const std::string& name : set.listed) {
            struct stat st {};
            if (!name.empty() && ::lstat(set.shown(name).c_str(), &st) == 0) found.push_back(name);
        }
        return found;
    }
    DIR* d = ::opendir(set.dir.empty() ? "." : set.dir.c_str());
    if (!d) return found;  // a missing directory: checkWritable reports it
    while (const dirent* e = ::readdir(d))
        if (set.contains(e->d_name)) found.push_back(e->d_name);
    ::closedir(d);
    return found;
}

}  // namespace

void checkOutputNames(const std::vector<OutputFlag>& outputs, const OutputFrames* frames,
                      const std::vector<InputFile>& inputs) {
    std::vector<NameSet> sets;
    for (const OutputFlag& out : outputs)
        if (!out.path.empty()) sets.push_back(namesOf(out, frames));

    // Two flags writing one name (the same spelling, or one directory reached
    // two ways: "a/../b", ".", a linked directory).
    for (size_t i = 0; i < sets.size(); ++i)
        for (size_t j = i + 1; j < sets.size(); ++j) {
            if (!sameDirectory(sets[i], sets[j])) continue;
            for (const NameSet* s : {&sets[i], &sets[j]}) {
                const NameSet& other = s == &sets[i] ? sets[j] : sets[i];
                for (const std::string& name : s->samples())
                    if (other.contains(name))
                        throw UsageError(sets[j].out->flag + " names the same file as " +
                                         sets[i].out->flag + " ('" + s->shown(name) + "')");
            }
        }

    std::unordered_map<FileKey, const InputFile*, FileKeyHash> read;
    for (const InputFile& in : inputs) read.emplace(in.key, &in);

    // Names that exist: compared by the identity of the file they lead to.
    struct Written {
        const NameSet* set;
        std::string name;
    };
    std::unordered_map<FileKey, Written, FileKeyHash> written;
    for (const NameSet& set : sets) {
        for (const std::string& name : existingNames(set)) {
            const std::string shown = set.shown(name);
            const std::string target = resolveOutputTarget(shown);
            const std::optional<FileKey> key = fileKeyOfPath(target);
            if (!key) continue;  // leads into a missing directory: checkWritable says so
            if (const auto in = read.find(*key); in != read.end())
                throw UsageError(set.out->flag + " '" + shown + "' names the same file as '" +
                                 in->second->path +
                                 "', which this render reads: an output never replaces an input");
            const auto [it, fresh] = written.emplace(*key, Written{&set, name});
            if (!fresh && !(it->second.set == &set && it->second.name == name))
                throw UsageError(set.out->flag + " '" + shown + "' and " + it->second.set->out->flag +
                                 " '" + it->second.set->shown(it->second.name) +
                                 "' are one file (a hard or symbolic link)");
            // A link to a name not created yet: clashes if another output writes that name.
            if (!key->newName.empty() && target != shown) {
                const FileKey dirKey{key->dev, key->ino, ""};
                for (const NameSet& other : sets)
                    if (other.dirKey && *other.dirKey == dirKey && other.contains(key->newName) &&
                        !(&other == &set && key->newName == name))
                        throw UsageError(set.out->flag + " '" + shown + "' is a link to " +
                                         other.out->flag + " '" + other.shown(key->newName) +
                                         "': both would write one file");
            }
        }
    }
}

}  // namespace raylab
