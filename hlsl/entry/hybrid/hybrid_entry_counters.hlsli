// What the hybrid entries that append to lists share: an atomic add to one word of the
// counters buffer (g_glint_counters, declared by the including entry), returning the old value.
#ifndef HYBRID_ENTRY_COUNTERS_HLSLI
#define HYBRID_ENTRY_COUNTERS_HLSLI

uint HybridEntryAddToCounter(uint counter, uint count)
{
    uint previous;
    InterlockedAdd(g_glint_counters[counter], count, previous);
    return previous;
}

#endif // HYBRID_ENTRY_COUNTERS_HLSLI
