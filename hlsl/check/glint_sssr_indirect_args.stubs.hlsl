// Header check of glint_sssr_indirect_args.hlsli: its callbacks are the shared stubs in
// check/stubs/sssr.stubs.hlsli (each defined once for every check).
#include "check/stubs/sssr.stubs.hlsli"

[numthreads(1, 1, 1)] void main()
{
    GLINT_SSSR_WriteIndirectArguments();
}
