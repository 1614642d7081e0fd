#pragma once
// A small, strict command-line parser: every value is validated, and any
// problem is a raylab::UsageError (exit code 2) naming the flag. Each command
// declares its flags (CommandFlags): the parser accepts "--flag value" and
// "--flag=value" alike, refuses an unknown flag with a "did you mean" hint,
// and the tests check that every declared flag is in the command's --help.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace raylab {

/// One flag of a command: its long name ("--width"), an optional short one
/// ("-o"), and whether a value follows it.
struct FlagSpec {
    std::string name;
    std::string shortName;
    bool takesValue = false;
};

/// What a command accepts: its name as typed after "raylab" ("bench accel"),
/// its --help text and its flags (-h/--help is implied).
struct CommandFlags {
    std::string command;
    const char* help = "";
    std::vector<FlagSpec> flags;

    /// Every flag name, long and short, help included (for hints).
    std::vector<std::string> names() const;
    const FlagSpec* find(const std::string& name) const;
};

class ArgParser {
public:
    ArgParser(std::vector<std::string> args, const CommandFlags& flags)
        : m_args(std::move(args)), m_flags(flags) {}

    bool done() const { return m_pos >= m_args.size(); }
    /// The next argument, consumed. A flag comes back as typed without any
    /// "=value" part (the value is then what value() returns); -h and --help
    /// print the command's help and exit 0; an undeclared flag is a
    /// UsageError with a "did you mean" hint.
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
    const CommandFlags& m_flags;
    size_t m_pos = 0;
    std::optional<std::string> m_inlineValue;  ///< the "value" of "--flag=value"
    std::vector<std::string> m_seen;  ///< flags whose value was read, by long name
};

}  // namespace raylab
