#include "tools/bench/effects_bench.h"

#include <algorithm>
#include <cstring>
#include <ostream>
#include <string>

#include "renderer/accel/accelerator.h"
#include "renderer/effects.h"
#include "renderer/io/scene_loader.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"

namespace raylab {

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string baseName(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

int runEffectsBench(const EffectsBenchOptions& options, std::ostream& out) {
    char line[512];
    std::snprintf(line, sizeof line, "%-16s %-62s %10s %10s %8s %12s %12s %9s\n", "scene", "effects",
                  "special_s", "general_s", "speedup", "rays_special", "rays_general", "identical");
    out << line;
    for (const std::string& path : options.scenes) {
        Scene scene = loadScene(path);
        RenderOverrides o;
        if (options.width) o.width = options.width;
        if (options.height) o.height = options.height;
        if (options.threads) o.threads = options.threads;
        o.spd = options.spd;
        const RenderOptions special = resolveRenderOptions(scene, o);
        o.effects = "all";
        const RenderOptions general = resolveRenderOptions(scene, o);
        auto accel = makeAccelerator(special.accel, scene, special.accelOptions);
        const EffectSet es = analyseEffects(scene, special), eg = analyseEffects(scene, general);

        std::vector<double> ts, tg;
        RenderResult rs, rg;
        for (int run = 0; run < std::max(1, options.runs); ++run) {
            rs = render(scene, *accel, special, es);  // interleaved: drift hits both alike
            rg = render(scene, *accel, general, eg);
            ts.push_back(rs.renderSeconds);
            tg.push_back(rg.renderSeconds);
        }
        const bool identical =
            std::memcmp(rs.film.rgba.data(), rg.film.rgba.data(), rs.film.rgba.size() * sizeof(float)) == 0;
        std::string names;
        for (const std::string& n : es.names()) names += (names.empty() ? "" : ",") + n;
        const double ms = median(ts), mg = median(tg);
        std::snprintf(line, sizeof line, "%-16s %-62s %10.4f %10.4f %7.2fx %12llu %12llu %9s\n",
                      baseName(path).c_str(), names.empty() ? "-" : names.c_str(), ms, mg, mg / ms,
                      (unsigned long long)rs.rays.total(), (unsigned long long)rg.rays.total(),
                      identical ? "yes" : "NO");
        out << line;
        if (!identical) return 1;
    }
    return 0;
}

}  // namespace raylab
