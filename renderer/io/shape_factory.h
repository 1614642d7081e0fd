#pragma once
// The one bridge from the geometry factories to located input errors: the
// factories (makeSphere, makePolygon, triangulatePolygon, Camera::perspective,
// ...) throw std::invalid_argument with a message that names the problem; a
// reader runs them through callFactory so the user gets FILE:LINE with it.

#include <stdexcept>
#include <string>
#include <utility>

#include "renderer/io/errors.h"

namespace raylab {

/// Runs `factory()`, turning its std::invalid_argument into
/// InputError(file, line, "<context>: <message>") (just the message when
/// `context`, e.g. a JSON key path, is empty).
template <class Factory>
auto callFactory(const std::string& file, int line, const std::string& context, Factory&& factory)
    -> decltype(factory()) {
    try {
        return std::forward<Factory>(factory)();
    } catch (const std::invalid_argument& e) {
        throw InputError(file, line, context.empty() ? e.what() : context + ": " + e.what());
    }
}

}  // namespace raylab
