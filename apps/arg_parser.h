#pragma once
// A small, strict command-line parser: every value is validated, and any
// problem is a raylab::UsageError (exit code 2) naming the flag.

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace raylab {

class ArgParser {
public:
    ArgParser(std::vector<std::string> args) : m_args(std::move(args)) {}

    bool done() const { return m_pos >= m_args.size(); }
    /// The next argument, consumed.
    std::string next();
    /// True when the next argument looks like a flag ("-x", "--xyz").
    bool peekFlag() const;
    /// The value after the flag `flag`, consumed (error when missing, or when
    /// the flag was given before: no silent "last one wins").
    std::string value(const std::string& flag);
    /// The value after a flag that may be given several times, each use
    /// adding one (-o: one output image per use), consumed.
    std::string repeatableValue(const std::string& flag);
    long long integer(const std::string& flag, long long lo, long long hi);
    double number(const std::string& flag, double lo, double hi);
    /// Three finite numbers written "X,Y,Z" (a point or a direction).
    std::array<double, 3> triple(const std::string& flag);
    /// One of `choices`.
    std::string choice(const std::string& flag, const std::vector<std::string>& choices) {
        return choices[choiceIndex(flag, choices)];
    }
    /// The value meant by one of the words of `choices` (a table of
    /// renderer/render_option_names.h).
    template <class E>
    E choice(const std::string& flag, const std::vector<std::pair<std::string, E>>& choices) {
        std::vector<std::string> words;
        for (const auto& entry : choices) words.push_back(entry.first);
        return choices[choiceIndex(flag, words)].second;
    }

private:
    /// Index in `words` of the value after `flag`; any other value is a
    /// UsageError that lists the words.
    size_t choiceIndex(const std::string& flag, const std::vector<std::string>& words);

    std::vector<std::string> m_args;
    size_t m_pos = 0;
    std::vector<std::string> m_seen;  ///< flags whose value was read (-o as --output)
};

}  // namespace raylab
