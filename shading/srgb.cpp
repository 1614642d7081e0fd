#include "shading/srgb.h"

namespace raylab {

const float* srgb8ToLinearTable() {
    static const struct Table {
        float v[256];
        Table() {
            for (int i = 0; i < 256; ++i) v[i] = float(srgbToLinear(i / 255.0));
        }
    } table;
    return table.v;
}

}  // namespace raylab
