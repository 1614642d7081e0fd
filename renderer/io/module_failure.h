#pragma once
// What a module's entry point caught, as the text it returns: nothing may be
// thrown across a dlopen boundary (image_module.h, exr_module.h).

#include <exception>
#include <new>
#include <string>

namespace raylab {

inline std::string describeFailure(const std::exception_ptr& p) {
    try {
        std::rethrow_exception(p);
    } catch (const std::bad_alloc&) {
        return "out of memory";
    } catch (const std::exception& e) {
        return e.what();
    } catch (...) {
        return "unknown failure";
    }
}

}  // namespace raylab
