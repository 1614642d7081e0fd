#pragma once
// The files a run will write, checked before it renders against the files it
// reads and against each other, by file identity (device and inode: through
// hard links, symbolic links, "." and ".."), so that no output replaces an
// input (`--stats meshes/torus.obj`) or another output of the same run.

#include <functional>
#include <string>
#include <vector>

#include "renderer/io/input_files.h"

namespace raylab {

/// One output flag and the path given to it.
struct OutputFlag {
    std::string flag;  ///< "-o", "--png", "--stats": names the flag in messages
    std::string path;
};

/// Numbered outputs: frame f of a flag's path is `nameOf(path, f)` for f in
/// [first, last]. The numbering may change only the file name, not the
/// directory, and must put the frame number as the last run of digits
/// before a fixed suffix ("out_0007.exr"), as sequenceFileName does.
struct OutputFrames {
    int first = 1, last = 1;
    std::function<std::string(const std::string&, int)> nameOf;
};

/// \brief Refuses outputs that are an input or one another.
///
/// Every name written (each frame's when `frames` is given) is compared:
/// with every other flag's names (the same name, or two names that are one
/// file through links), and, where it exists, with every input by identity.
/// Cost: one stat per existing output name; with more than 64 frames, one
/// scan of each output directory instead of a stat per frame.
/// \throws UsageError naming the flag(s), the output name and the input.
void checkOutputNames(const std::vector<OutputFlag>& outputs, const OutputFrames* frames,
                      const std::vector<InputFile>& inputs);

}  // namespace raylab
