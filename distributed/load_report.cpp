#include "distributed/load_report.h"

#include <cstdio>

namespace raylab {

std::string formatLoadReport(const DistributedReport& report) {
    if (report.loads.empty()) return "";
    uint64_t bytes = 0, items = 0;
    for (const RankLoad& l : report.loads) {
        bytes += l.bytesSent;
        items += l.items;
    }
    char line[512];
    std::snprintf(line, sizeof line, "  ranks:    %d ranks, %d %s, %.1f MiB gathered in %.3f s\n",
                  report.ranks, report.items, report.spd ? "corner rows" : "tiles",
                  double(bytes) / (1024.0 * 1024.0), report.seconds);
    std::string s = line;
    for (const RankLoad& l : report.loads) {
        std::snprintf(line, sizeof line,
                      "    rank %d (%s, %d thread%s): %llu items (%.1f%%) in %llu chunks, busy "
                      "%.3f s (cpu %.3f s), done at %.3f s, %.2f Mrays\n",
                      l.rank, l.host.c_str(), l.threads, l.threads == 1 ? "" : "s",
                      (unsigned long long)l.items,
                      items ? 100.0 * double(l.items) / double(items) : 0.0,
                      (unsigned long long)l.chunks, l.busySeconds, l.cpuSeconds, l.finishSeconds,
                      double(l.rays) * 1e-6);
        s += line;
    }
    return s;
}

}  // namespace raylab
