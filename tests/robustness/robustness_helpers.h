#pragma once
// Shared by the robustness tests: running the real raylab binary with a
// deadline, a scratch directory whose contents are checked afterwards, and
// the checks every refused input must pass (exit code, exactly one
// "raylab: error: " line, nothing written).

#include <doctest/doctest.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/temp_dir.h"

namespace raylab::robust {

using test::readFile;
using test::TempDir;

/// A valid JSON scene: one sphere, one light, the default image size.
inline const std::string kSphereScene =
    "{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n"
    " \"lights\": [{\"type\": \"point\", \"position\": [2, 3, 4]}],\n"
    " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1}]}\n";

/// Issue 22's deep tree: a glass sphere inside a mirror sphere, 4x4 pixels at
/// depth 64, weights that never fall to zero. The ray tree doubles at every
/// level: only the per-sample ray cap ends it (test_ray_cap.cpp), and only a
/// stop check inside the tree interrupts it promptly (test_signals.cpp).
inline const std::string kGlassInMirrorScene =
    "{\"image\": {\"width\": 4, \"height\": 4, \"depth\": 64},\n"
    " \"camera\": {\"eye\": [0, 0, 0.5], \"look_at\": [0, 0, -1], \"fov\": 30},\n"
    " \"lights\": [{\"type\": \"point\", \"position\": [0.2, 0.3, 0.4]}],\n"
    " \"materials\": {\"mirror\": {\"kd\": 0.05, \"km\": 0.9},\n"
    "               \"glass\": {\"kd\": 0, \"km\": 0.1, \"kt\": 0.9, \"ior\": 1.5}},\n"
    " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 3, \"material\": \"mirror\",\n"
    "               \"sides\": \"inside\"},\n"
    "              {\"type\": \"sphere\", \"center\": [0, 0, -1], \"radius\": 0.5, \"material\": \"glass\"}]}\n";

/// The lines of `text` without their '\n' (a last line without one counts).
inline std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) out.push_back(line);
    return out;
}

/// At most the first 300 bytes of `s`, for failure messages: a test that
/// catches a 1 MB error line must not print it.
inline std::string head(const std::string& s) {
    return s.size() <= 300 ? s : s.substr(0, 300) + "... (" + std::to_string(s.size()) + " bytes)";
}

inline bool startsWith(const std::string& s, const std::string& prefix) {
    return s.compare(0, prefix.size(), prefix) == 0;
}

inline bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

/// A raylab process started in the background (stdin /dev/null, stdout and
/// stderr to files), for tests that signal it or bound its run time.
class Process {
public:
    /// `addressSpaceLimit` > 0 runs raylab under that RLIMIT_AS (`ulimit -v`), in bytes.
    /// `env` adds or replaces environment variables ("NAME=value").
    /// `outFile` "" leaves stdout closed; "|" makes it a pipe whose reading end is closed.
    Process(const std::vector<std::string>& args, const std::string& outFile,
            const std::string& errFile, double addressSpaceLimit = 0,
            const std::vector<std::string>& env = {}) {
        struct rlimit as {};
        ::getrlimit(RLIMIT_AS, &as);
        if (addressSpaceLimit > 0) as.rlim_cur = rlim_t(addressSpaceLimit);
        std::vector<std::string> all{RAYLAB_BINARY};
        all.insert(all.end(), args.begin(), args.end());
        std::vector<char*> argv;
        for (std::string& a : all) argv.push_back(a.data());
        argv.push_back(nullptr);
        // The environment is built before fork: the child may only exec.
        std::vector<std::string> vars = env;
        for (char** e = environ; *e; ++e) {
            const std::string var = *e;
            const std::string name = var.substr(0, var.find('='));
            if (std::none_of(env.begin(), env.end(),
                             [&](const std::string& v) { return v.substr(0, v.find('=')) == name; }))
                vars.push_back(var);
        }
        std::vector<char*> envp;
        for (std::string& v : vars) envp.push_back(v.data());
        envp.push_back(nullptr);
        int pipeFds[2] = {-1, -1};
        if (outFile == "|" && ::pipe(pipeFds) != 0) return;
        m_start = std::chrono::steady_clock::now();
        // Signals sent right after fork must not reach the test framework's
        // own handlers in the child (it is still a copy of this process until
        // exec): block them across fork, reset them to default in the child,
        // and only then unblock. A SIGINT that arrives before exec then ends
        // the child as it would end raylab before main.
        sigset_t blocked, previous;
        sigfillset(&blocked);
        ::pthread_sigmask(SIG_SETMASK, &blocked, &previous);
        m_pid = ::fork();
        if (m_pid == 0) {
            // Child: only async-signal-safe calls until exec.
            for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGSEGV, SIGABRT, SIGFPE, SIGILL, SIGBUS})
                ::signal(sig, SIG_DFL);
            ::sigprocmask(SIG_SETMASK, &previous, nullptr);
            if (addressSpaceLimit > 0 && ::setrlimit(RLIMIT_AS, &as) != 0) ::_exit(125);
            const int in = ::open("/dev/null", O_RDONLY);
            const int out = outFile == "|" ? pipeFds[1]
                            : outFile.empty()
                                ? -2
                                : ::open(outFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            const int err = ::open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            if (in < 0 || out == -1 || err < 0) ::_exit(126);
            ::dup2(in, 0);
            if (out >= 0) ::dup2(out, 1);
            else ::close(1);
            ::dup2(err, 2);
            if (pipeFds[0] >= 0) ::close(pipeFds[0]);
            ::execve(argv[0], argv.data(), envp.data());
            ::_exit(127);
        }
        // The reading end goes away at once: raylab's stdout is a broken pipe.
        if (pipeFds[0] >= 0) {
            ::close(pipeFds[0]);
            ::close(pipeFds[1]);
        }
        ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    }
    ~Process() {
        if (m_pid > 0 && !m_reaped) {
            ::kill(m_pid, SIGKILL);
            int status = 0;
            ::waitpid(m_pid, &status, 0);
        }
    }
    Process(const Process&) = delete;
    Process& operator=(const Process&) = delete;

    bool started() const { return m_pid > 0; }
    /// Waits until the process has stopped itself (RAYLAB_TEST_STOP_AT) or
    /// exited; true when it is stopped. No timing: waitpid(WUNTRACED) blocks.
    bool waitUntilStopped() {
        int status = 0;
        if (::waitpid(m_pid, &status, WUNTRACED) != m_pid) return false;
        if (WIFSTOPPED(status)) return true;
        m_reaped = true;
        m_exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        return false;
    }
    pid_t pid() const { return m_pid; }
    void signal(int sig) const {
        if (m_pid > 0 && !m_reaped) ::kill(m_pid, sig);
    }
    double secondsSinceStart() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    }
    /// True once the process has exited (reaped); polls for at most `seconds`.
    bool wait(double seconds) {
        if (m_reaped) return true;
        const auto deadline = std::chrono::steady_clock::now() +
                              std::chrono::duration<double>(seconds);
        while (true) {
            int status = 0;
            const pid_t r = ::waitpid(m_pid, &status, WNOHANG);
            if (r == m_pid) {
                m_reaped = true;
                m_exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
                return true;
            }
            if (std::chrono::steady_clock::now() >= deadline) return false;
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
    /// Exit status (128 + signal for a killed process); -1 before wait() succeeded.
    int exitCode() const { return m_exitCode; }

private:
    pid_t m_pid = -1;
    bool m_reaped = false;
    int m_exitCode = -1;
    std::chrono::steady_clock::time_point m_start;
};

struct RunResult {
    int exitCode = -1;      ///< 128 + signal when killed; -1 when it had to be killed
    bool timedOut = false;  ///< still running after the deadline (a hang)
    double seconds = 0;
    std::string out, err;
};

/// Runs `raylab ARGS` with a deadline; a process still running after
/// `timeoutSeconds` is killed and reported as timed out.
inline RunResult runRaylab(const std::vector<std::string>& args, double timeoutSeconds = 60,
                           double addressSpaceLimit = 0, const std::vector<std::string>& env = {}) {
    const TempDir io;
    RunResult r;
    {
        Process p(args, io.file("stdout"), io.file("stderr"), addressSpaceLimit, env);
        REQUIRE(p.started());
        if (p.wait(timeoutSeconds)) {
            r.exitCode = p.exitCode();
        } else {
            r.timedOut = true;
            p.signal(SIGKILL);
            p.wait(10);
        }
        r.seconds = p.secondsSinceStart();
    }
    r.out = readFile(io.file("stdout"));
    r.err = readFile(io.file("stderr"));
    return r;
}

/// `render SCENE -o DIR/out.exr --png DIR/out.png --width 8 --height 8 --quiet`
/// plus `extra`, where DIR is the scene's scratch directory.
inline std::vector<std::string> tinyRender(const TempDir& dir, const std::string& scene,
                                           const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args{"render", scene, "-o", dir.file("out.exr"), "--png",
                                  dir.file("out.png"), "--width", "8", "--height", "8",
                                  "--quiet", "--threads", "2"};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
}

/// The contract for refused input: exit `code`, stderr is exactly one line,
/// "raylab: error: " + `location` + ..., containing `fragment`, and `dir`
/// holds exactly `inputs` afterwards (no output, no temporary file).
/// `location` is "FILE:LINE:" or "FILE:" for a whole-file problem, "" for usage.
inline void checkRefused(const RunResult& r, const TempDir& dir,
                         const std::vector<std::string>& inputs, int code,
                         const std::string& location, const std::string& fragment) {
    const std::string err = head(r.err);
    CAPTURE(err);
    CHECK_FALSE(r.timedOut);
    CHECK(r.exitCode == code);
    const std::vector<std::string> errLines = lines(r.err);
    CHECK(errLines.size() == 1);
    if (!errLines.empty()) {
        CHECK(startsWith(errLines[0], "raylab: error: " + location));
        CHECK(contains(errLines[0], fragment));
        CHECK(errLines[0].size() < 400);  // one readable line, not a dump of the input
        // No raw control bytes from the input: an ESC sequence or a carriage
        // return would rewrite the terminal line instead of showing it.
        for (char c : errLines[0]) {
            const unsigned char u = static_cast<unsigned char>(c);
            CHECK_MESSAGE((u >= 0x20 && u != 0x7f), "raw control byte in the error line");
        }
    }
    std::vector<std::string> expected = inputs;
    std::sort(expected.begin(), expected.end());
    CHECK(dir.files() == expected);
}

/// The contract for accepted input: exit 0, an EXR and a PNG written, no
/// temporary file left, and stderr holding only "raylab: warning: " lines.
inline void checkRendered(const RunResult& r, const TempDir& dir,
                          const std::vector<std::string>& inputs) {
    const std::string err = head(r.err);
    CAPTURE(err);
    CHECK_FALSE(r.timedOut);
    CHECK(r.exitCode == 0);
    for (const std::string& line : lines(r.err)) CHECK(startsWith(line, "raylab: warning: "));
    std::vector<std::string> expected = inputs;
    expected.push_back("out.exr");
    expected.push_back("out.png");
    std::sort(expected.begin(), expected.end());
    CHECK(dir.files() == expected);
}

}  // namespace raylab::robust

namespace raylab::robust {

/// For inputs that may legitimately go either way (extreme but finite
/// values): rendered (checkRendered) or refused (checkRefused with exit 1
/// and `location`), never a crash, a hang or a half-written file.
inline void checkHandled(const RunResult& r, const TempDir& dir,
                         const std::vector<std::string>& inputs, const std::string& location) {
    if (r.exitCode == 0)
        checkRendered(r, dir, inputs);
    else
        checkRefused(r, dir, inputs, 1, location, "");
}

}  // namespace raylab::robust
