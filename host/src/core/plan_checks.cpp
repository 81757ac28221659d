#include "core/plan_checks.h"

namespace glint {

const char* resultName(Result result) {
    switch (result) {
    case Result::Ok:
        return "ok";
    case Result::InvalidArgument:
        return "invalid argument";
    case Result::Unsupported:
        return "unsupported";
    case Result::DeviceError:
        return "device error";
    }
    return "unknown result";
}

namespace core {

Result invalidArgument(std::string* error, std::string_view effect, const std::string& message) {
    if (error) *error = std::string(effect) + ": " + message;
    return Result::InvalidArgument;
}

} // namespace core
} // namespace glint
