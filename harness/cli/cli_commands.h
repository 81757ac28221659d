// The verbs of the glint command. Each returns the process exit code.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace glint::cli {

// Exit codes shared by every verb.
enum ExitCode : int {
    kExitOk = 0,
    kExitCheckFailed = 1, // the command ran and a check it makes failed
    kExitUsage = 2,       // bad arguments or unreadable/malformed input
};

struct BenchOptions {
    std::string effect;
    uint32_t width = 1920, height = 1080;
    uint32_t runs = 200;
    uint32_t levels = 0; // depth pyramid: 0 = full chain
    bool reversed = false;
    bool farthest = false;
    bool skipLevel0 = false;           // depth pyramid: leave level 0 unwritten
    std::string scene;                 // sssr: the scene to simulate (default the glossy room)
    std::vector<std::string> settings; // sssr: "name=value" desc overrides
    bool validate = false;
};

struct SimulateOptions {
    std::string scenePath;
    std::string outDir;
    uint32_t width = 0, height = 0; // 0: the scene's resolution
    uint32_t frames = 0;            // 0: the scene's frame count
    uint32_t spp = 0;               // 0: the scene's reference samples per pixel
    std::optional<uint32_t> seed;
    bool validate = false;
};

int runDevices(bool validate);
int runSimulate(const SimulateOptions& options);
int runBench(const BenchOptions& options);
int runInfo(const std::string& path, bool loadPixels);

} // namespace glint::cli
