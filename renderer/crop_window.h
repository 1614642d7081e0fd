#pragma once
// A crop (region) render, as pbrt's --cropwindow: a window of the image in
// NDC, y from the top, that selects the pixels [ceil(x0·W), ceil(x1·W)) ×
// [ceil(y0·H), ceil(y1·H)). Only those pixels are rendered, each exactly as
// in the full frame (docs: raylab render --help).

namespace raylab {

/// The window in normalised device coordinates: 0 ≤ x0 < x1 ≤ 1, 0 ≤ y0 < y1 ≤ 1.
struct CropWindow {
    double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
    bool isFull() const { return x0 == 0 && x1 == 1 && y0 == 0 && y1 == 1; }
};

/// Pixels [x0, x1) × [y0, y1) of a width × height image.
struct PixelWindow {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool empty() const { return x1 <= x0 || y1 <= y0; }
};

/// The pixels `crop` selects in a width × height image (may be empty when
/// the window is thinner than a pixel).
PixelWindow cropPixels(const CropWindow& crop, int width, int height);

}  // namespace raylab
