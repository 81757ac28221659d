// The verbs of the glint command. Each returns the process exit code.
#pragma once

#include <string>

namespace glint::cli {

// Exit codes shared by every verb.
enum ExitCode : int {
    kExitOk = 0,
    kExitCheckFailed = 1, // the command ran and a check it makes failed
    kExitUsage = 2,       // bad arguments or unreadable/malformed input
};

int runDevices(bool validate);
int runInfo(const std::string& path, bool loadPixels);

} // namespace glint::cli
