// The buffers every header check's stub callbacks read and write (values are arbitrary: a check
// only compiles), and an atomic add for the stubs of counter callbacks.
#ifndef GLINT_CHECK_BUFFERS_HLSLI
#define GLINT_CHECK_BUFFERS_HLSLI

RWStructuredBuffer<float4> g_glint_check;
RWStructuredBuffer<uint> g_glint_check_words;

uint GLINT_CHECK_Add(uint word, uint count)
{
    uint previous;
    InterlockedAdd(g_glint_check_words[word], count, previous);
    return previous;
}

#endif // GLINT_CHECK_BUFFERS_HLSLI
