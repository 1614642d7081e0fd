#include "renderer/render_option_names.h"

#include <initializer_list>

namespace raylab {

namespace {

/// The table of `values`, each under the word `nameOf` gives it.
template <class E, class NameOf>
OptionNames<E> tableOf(std::initializer_list<E> values, NameOf nameOf) {
    OptionNames<E> names;
    for (E v : values) names.emplace_back(nameOf(v), v);
    return names;
}

}  // namespace

const char* precisionName(Precision precision) {
    return precision == Precision::Float ? "float" : "double";
}

const OptionNames<AcceleratorKind>& acceleratorNames() {
    static const auto names =
        tableOf({AcceleratorKind::Embree, AcceleratorKind::Naive}, acceleratorName);
    return names;
}

const OptionNames<AccelOptions::BvhQuality>& bvhQualityNames() {
    using Q = AccelOptions::BvhQuality;
    static const auto names = tableOf({Q::Low, Q::Medium, Q::High}, bvhQualityName);
    return names;
}

const OptionNames<Precision>& precisionNames() {
    static const auto names = tableOf({Precision::Float, Precision::Double}, precisionName);
    return names;
}

const OptionNames<EffectsMode>& effectsModeNames() {
    static const OptionNames<EffectsMode> names = {{"auto", EffectsMode::Auto},
                                                   {"all", EffectsMode::All}};
    return names;
}

const OptionNames<ShadowMode>& shadowModeNames() {
    static const auto names = tableOf({ShadowMode::Opaque, ShadowMode::Filtered}, shadowModeName);
    return names;
}

const OptionNames<TextureFilter>& textureFilterNames() {
    static const auto names = tableOf({TextureFilter::Point, TextureFilter::Bilinear,
                                       TextureFilter::Trilinear, TextureFilter::Anisotropic},
                                      textureFilterName);
    return names;
}

const OptionNames<TextureFootprint>& textureFootprintNames() {
    static const auto names = tableOf(
        {TextureFootprint::Cones, TextureFootprint::Differentials}, textureFootprintName);
    return names;
}

}  // namespace raylab
