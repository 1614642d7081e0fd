// raylab-openimageio-probe MODULE IMAGE: loads raylab's OpenImageIO module
// and reads IMAGE through it, then prints how much address space that took
// (bytes, one line). raylab runs it before loading the module itself under a
// finite `ulimit -v`: OpenImageIO's library constructors do not fail but
// crash when the address space runs out inside dlopen, so the cost is
// measured in a process that may crash (image_module_loader.cpp).

#include <dlfcn.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "renderer/io/image_module.h"

namespace {

/// This process's address space in use, from /proc/self/statm (pages).
double addressSpaceBytes() {
    std::FILE* f = std::fopen("/proc/self/statm", "r");
    if (!f) return -1;
    double pages = -1;
    if (std::fscanf(f, "%lf", &pages) != 1) pages = -1;
    std::fclose(f);
    return pages * 4096.0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) return 2;
    const double before = addressSpaceBytes();
    void* handle = ::dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!handle) return 3;
    using Entry = const raylab::image_module::Api* (*)();
    auto entry = reinterpret_cast<Entry>(::dlsym(handle, raylab::image_module::kEntryPoint));
    const raylab::image_module::Api* api = entry ? entry() : nullptr;
    if (!api || api->version != raylab::image_module::kVersion) return 4;
    // Reading a real image starts whatever OpenImageIO starts lazily (format
    // plug-ins, thread pools); a file it cannot read is fine.
    std::string error;
    if (auto file = api->open(argv[2], error)) {
        const raylab::image_module::ImageHeader& h = file->header();
        if (h.width > 0 && h.height > 0 && h.channels > 0 &&
            double(h.width) * h.height * h.channels <= 4096.0 * 4096.0 * 4) {
            std::vector<float> texels(size_t(h.width) * size_t(h.height) * size_t(h.channels));
            (void)file->readFloat(h.channels, texels.data(), error);
        }
    }
    std::printf("%.0f\n", addressSpaceBytes() - before);
    return 0;
}
