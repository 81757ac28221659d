// The effects glint ships, in the order a tool runs them: one line per effect, each naming the
// function its own file defines (host/src/core/effects/<effect>_effect.cpp).
GLINT_EFFECT(depthPyramidEffect)
GLINT_EFFECT(roughnessEffect)
GLINT_EFFECT(reflectionsEffect)
GLINT_EFFECT(hybridEffect)
GLINT_EFFECT(shadowsEffect)
