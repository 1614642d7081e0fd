#pragma once
// Reads an OpenEXR image back into a Film (for tests and `raylab accuracy`).

#include <string>

#include "renderer/film.h"

namespace raylab {

/// \brief Reads the channels that writeExr produces from the OpenEXR file `path`.
///
/// HALF channels are widened to float exactly. The Film always has rgba sized
/// width*height*4: missing R, G or B channels read as 0 and a missing A as 1
/// (the OpenEXR convention for an opaque image). An AOV layer (Z; distance;
/// N.X/N.Y/N.Z; albedo.R/G/B; objectId) whose channels are all absent is left as an empty
/// vector; a partly present layer reads its missing components as 0. The
/// Cryptomatte layers are not read (Film::mattes stays empty).
/// \throws InputError(path, 0, reason) when the file cannot be opened or read.
Film readExr(const std::string& path);

}  // namespace raylab
