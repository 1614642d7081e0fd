#pragma once
// The render settings that define an image, as one line of "name=value"
// words: what ranks compare under mpirun (distributed/render_identity.h) and
// what the EXR header records (raylab/settings), so that two files with the
// same words were rendered the same way.

#include <string>

#include "renderer/render_options.h"

namespace raylab {

/// Every field of RenderOptions that changes pixels, doubles to 17 digits
/// (not `threads`: the image does not depend on it). A field added to
/// RenderOptions that changes pixels belongs here too.
std::string renderSettingsText(const RenderOptions& options);

}  // namespace raylab
