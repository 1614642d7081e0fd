#include "renderer/crop_window.h"

#include <algorithm>
#include <cmath>

namespace raylab {

PixelWindow cropPixels(const CropWindow& crop, int width, int height) {
    // pbrt's rule: a pixel belongs to the window when its centre-left edge
    // does, so adjacent windows tile the image without gap or overlap.
    const auto edge = [](double t, int size) {
        return std::clamp(int(std::ceil(t * size)), 0, size);
    };
    return {edge(crop.x0, width), edge(crop.y0, height), edge(crop.x1, width),
            edge(crop.y1, height)};
}

}  // namespace raylab
