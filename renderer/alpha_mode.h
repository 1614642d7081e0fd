#pragma once
// What the alpha channel of a render means where camera rays miss every
// object (docs/output.md has the compositing rules).

namespace raylab {

enum class AlphaMode {
    /// RGB keeps the background colour, A = the fraction of the pixel's
    /// samples that hit an object: raylab's historical output (the default).
    /// A is then a matte of the objects, not the alpha of an "over".
    Background,
    /// Camera rays that miss contribute no colour and A = coverage: RGB is
    /// premultiplied by A, ready for an "over" onto another plate.
    Transparent,
    /// RGB as Background and A = 1 everywhere: an opaque plate.
    Opaque,
};

/// "background", "transparent" or "opaque": the spelling of --alpha.
inline const char* alphaModeName(AlphaMode m) {
    return m == AlphaMode::Background ? "background"
                                      : m == AlphaMode::Transparent ? "transparent" : "opaque";
}

}  // namespace raylab
