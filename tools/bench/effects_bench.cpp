#include "tools/bench/effects_bench.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <ostream>
#include <string>

#include "renderer/accel/accelerator.h"
#include "renderer/effects.h"
#include "renderer/huge_page_allocator.h"
#include "renderer/io/scene_loader.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"
#include "tools/report/phase_clock.h"
#include "tools/report/table_format.h"

namespace raylab {

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
        o.effects = EffectsMode::All;
        const RenderOptions general = resolveRenderOptions(scene, o);
        auto accel = makeAccelerator(special.accel, scene, special.accelOptions);
        const EffectSet es = analyseEffects(scene, special), eg = analyseEffects(scene, general);

        std::vector<double> ts, tg;
        RenderResult rs, rg;
        const huge_pages::ReuseScope reuseFrameBuffers;  // as render --frames does
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
                      fileName(path).c_str(), names.empty() ? "-" : names.c_str(), ms, mg, mg / ms,
                      (unsigned long long)rs.rays.total(), (unsigned long long)rg.rays.total(),
                      identical ? "yes" : "NO");
        out << line;
        if (!identical) return 1;
    }
    return 0;
}

}  // namespace raylab
