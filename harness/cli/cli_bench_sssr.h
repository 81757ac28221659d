// glint bench sssr (cli_bench_sssr.cpp).
#pragma once

#include "cli_commands.h"

#include "glint/glint_sssr.h"

#include <gpu/gpu_context.h>

#include <string>

namespace glint::cli {

int runBenchSssr(const BenchOptions& options, const gpu::Context& context);

} // namespace glint::cli
