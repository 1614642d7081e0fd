#include "tools/bench/ingest_bench.h"

#include <sys/resource.h>  // getrusage: the process CPU time
#include <malloc.h>  // malloc_trim: freed memory back to the OS before each baseline
#include <stdlib.h>  // mkdtemp

#include <tbb/global_control.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>

#include "renderer/io/errors.h"
#include "renderer/io/load_warnings.h"
#include "renderer/io/obj_loader.h"
#include "renderer/io/obj_parser.h"
#include "renderer/io/text_file.h"
#include "tools/report/machine.h"
#include "tools/report/phase_clock.h"

namespace raylab {

namespace {

/// The same terrain as the height-field scene of `bench accel`.
double terrainHeight(double x, double y) {
    return 0.12 * std::sin(3.1 * x + 0.7) * std::cos(2.3 * y) +
           0.06 * std::sin(7.3 * x + 5.1 * y) + 0.03 * std::cos(13.7 * x - 9.1 * y);
}

void appendFixed(std::string& out, double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 6);
    out.append(buf, r.ptr);
}

void appendIndex(std::string& out, size_t v) {
    char buf[24];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}

/// A value of /proc/self/status in bytes ("VmRSS", "VmHWM"), or 0.
size_t statusBytes(const char* key) {
    std::ifstream in("/proc/self/status");
    std::string line;
    const std::string prefix = std::string(key) + ":";
    while (std::getline(in, line))
        if (line.compare(0, prefix.size(), prefix) == 0)
            return size_t(std::strtoull(line.c_str() + prefix.size(), nullptr, 10)) * 1024;
    return 0;
}

/// Returns freed heap to the OS and restarts the peak (VmHWM) at the current
/// RSS; returns that RSS, the baseline of the next measurement.
size_t resetPeak() {
    malloc_trim(0);
    std::ofstream("/proc/self/clear_refs") << "5";
    return statusBytes("VmRSS");
}

/// CPU seconds of the whole process so far (all threads, user + system).
double processCpuSeconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

struct Sample {
    double seconds = 0;
    double cpuSeconds = 0;  ///< of every thread: a loaded machine inflates it less than wall time
    double peakBytes = 0;  ///< peak RSS above the baseline
};

template <class F>
Sample measure(F&& load) {
    const size_t base = resetPeak();
    const double c0 = processCpuSeconds();
    const auto t0 = std::chrono::steady_clock::now();
    load();
    Sample s;
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    s.cpuSeconds = processCpuSeconds() - c0;
    const size_t peak = statusBytes("VmHWM");
    s.peakBytes = peak > base ? double(peak - base) : 0.0;
    return s;
}

}  // namespace

std::string heightFieldObj(size_t grid) {
    const size_t n = grid + 1;
    std::string out;
    out.reserve(n * n * 34 + grid * grid * 34 + 64);
    out += "# raylab bench ingest: height field of " + std::to_string(grid) + "x" +
           std::to_string(grid) + " quads\nmtllib terrain.mtl\ns 1\n";
    for (size_t j = 0; j < n; ++j) {
        for (size_t i = 0; i < n; ++i) {
            const double x = -1.0 + 2.0 * double(i) / double(grid);
            const double y = -1.0 + 2.0 * double(j) / double(grid);
            out += "v ";
            appendFixed(out, x);
            out += ' ';
            appendFixed(out, y);
            out += ' ';
            appendFixed(out, terrainHeight(x, y));
            out += '\n';
        }
    }
    int band = -1;
    for (size_t j = 0; j < grid; ++j) {
        const int b = int(4 * j / grid);
        if (b != band) {
            band = b;
            out += "usemtl band" + std::to_string(b) + "\n";
        }
        for (size_t i = 0; i < grid; ++i) {
            const size_t v00 = j * n + i + 1;  // 1-based
            out += "f ";
            appendIndex(out, v00);
            out += ' ';
            appendIndex(out, v00 + 1);
            out += ' ';
            appendIndex(out, v00 + n + 1);
            out += ' ';
            appendIndex(out, v00 + n);
            out += '\n';
        }
    }
    return out;
}

std::string heightFieldMtl() {
    return "newmtl band0\nKd 0.35 0.45 0.25\nKs 0.1 0.1 0.1\nNs 10\n"
           "newmtl band1\nKd 0.5 0.45 0.3\nKs 0.1 0.1 0.1\nNs 10\n"
           "newmtl band2\nKd 0.55 0.5 0.45\nKs 0.1 0.1 0.1\nNs 10\n"
           "newmtl band3\nKd 0.9 0.9 0.92\nKs 0.3 0.3 0.3\nNs 40\n";
}

int runIngestBench(const IngestBenchOptions& options, std::ostream& out) {
    if (options.triangles < 2) throw UsageError("bench ingest: --triangles must be at least 2");
    if (options.runs < 1) throw UsageError("bench ingest: --runs must be at least 1");
    namespace fs = std::filesystem;
    std::string dir = options.dir;
    bool removeDir = false;
    if (dir.empty()) {
        std::string name = (fs::temp_directory_path() / "raylab_ingest_XXXXXX").string();
        if (!::mkdtemp(name.data())) throw InputError(name, 0, "cannot create a temp folder");
        dir = name;
        removeDir = !options.keep;
    }
    const size_t grid = size_t(std::max(1.0, std::round(std::sqrt(double(options.triangles) / 2))));
    const std::string objPath = (fs::path(dir) / "terrain.obj").string();
    size_t bytes = 0;
    {
        const std::string obj = heightFieldObj(grid);
        bytes = obj.size();
        std::ofstream f(objPath, std::ios::binary);
        f << obj;
        if (!f.good()) throw InputError(objPath, 0, "cannot write the generated OBJ");
        std::ofstream m((fs::path(dir) / "terrain.mtl").string(), std::ios::binary);
        m << heightFieldMtl();
        if (!m.good()) throw InputError(dir + "/terrain.mtl", 0, "cannot write the generated MTL");
    }
    const size_t triangles = 2 * grid * grid;

    char line[256];
    out << "raylab bench ingest: " << cpuModelName() << ", " << logicalCores()
        << " logical cores, load average " << loadAverage() << "\n";
    std::snprintf(line, sizeof line,
                  "OBJ: %s, %.1f MB, %zux%zu quads = %zu triangles, no vn (s 1), 4 materials\n",
                  objPath.c_str(), double(bytes) / 1e6, grid, grid, triangles);
    out << line << "medians of " << options.runs
        << " runs; wall-clock and process CPU time (all threads); bytes/tri: peak RSS above the\n"
           "baseline measured just before each load, per triangle\n";
    std::snprintf(line, sizeof line, "%-8s %-18s %9s %9s %9s %9s %12s\n", "threads", "phase",
                  "wall_s", "MB/s", "cpu_s", "cpu_MB/s", "bytes/tri");
    out << line;

    for (int threads : options.threads) {
        const int t = effectiveThreads(threads);
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(t));
        std::vector<double> loadS, loadCpu, loadPeak, parseS, parseCpu, parsePeak;
        ObjLoadOptions quiet;
        quiet.printWarnings = false;
        for (int run = 0; run < options.runs; ++run) {
            // Interleaved: drift on a shared machine hits both phases alike.
            size_t got = 0;
            Sample s = measure([&] {
                const ObjModel m = loadObj(objPath, quiet);
                got = m.triangleCount();
            });
            if (got != triangles)
                throw InputError(objPath, 0, "loaded " + std::to_string(got) + " triangles, expected " +
                                                 std::to_string(triangles));
            loadS.push_back(s.seconds);
            loadCpu.push_back(s.cpuSeconds);
            loadPeak.push_back(s.peakBytes);
            s = measure([&] {
                const std::string text = readTextFile(objPath);
                LoadWarnings warn(objPath);
                const ObjData d = parseObj(text, objPath, warn);
                got = d.faces.size();
            });
            parseS.push_back(s.seconds);
            parseCpu.push_back(s.cpuSeconds);
            parsePeak.push_back(s.peakBytes);
        }
        const auto row = [&](const char* phase, const std::vector<double>& secs,
                             const std::vector<double>& cpu, const std::vector<double>& peak) {
            const double m = median(secs), c = median(cpu), p = median(peak);
            const double mb = double(bytes) / 1e6;
            std::snprintf(line, sizeof line, "%-8d %-18s %9.3f %9.1f %9.3f %9.1f %12.1f\n", t,
                          phase, m, mb / m, c, mb / c, p / double(triangles));
            out << line;
        };
        row("loadObj (whole)", loadS, loadCpu, loadPeak);
        row("read + parseObj", parseS, parseCpu, parsePeak);
    }
    out << "bar (issue 20): loadObj >= 100 MB/s on all cores, peak <= 150 bytes/triangle\n";
    if (removeDir) {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
    return 0;
}

}  // namespace raylab
