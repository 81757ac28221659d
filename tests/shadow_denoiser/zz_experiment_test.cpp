// TEMPORARY experiment (not to be committed): CPU pipeline variants on the courtyard frames.
#include "reference/shadow_denoiser_reference.h"
#include "shadow_denoiser/shadow_runner.h"
#include "support/gpu_test_context.h"

#include "replay/replay_shadow.h"
#include "replay/replay_sssr.h"
#include "scene/scene_file.h"
#include "scene/scene_simulate.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

using namespace glint;

namespace {
struct Frames {
    std::uint32_t w = 0, h = 0, n = 0;
    std::vector<std::vector<float>> vis, ref;
    std::vector<float> depth, normals;
    float vd[3];
};

constexpr float kG[9] = {0.11082929f, 0.10679958f, 0.09556847f, 0.07941266f, 0.06127663f,
                         0.04390662f, 0.02921428f, 0.01805055f, 0.01035657f};

Frames load(std::uint32_t frames, std::uint32_t W, std::uint32_t H) {
    Frames f;
    char path[256];
    std::snprintf(path, sizeof path, "/tmp/exp/frames_%ux%u_%u.bin", W, H, frames);
    std::ifstream in(path, std::ios::binary);
    auto rd = [&](std::vector<float>& v, std::size_t n) { v.resize(n); in.read((char*)v.data(), n * 4); };
    if (in) {
        in.read((char*)&f.w, 4); in.read((char*)&f.h, 4); in.read((char*)&f.n, 4); in.read((char*)f.vd, 12);
        std::size_t c = std::size_t(f.w) * f.h;
        rd(f.depth, c); rd(f.normals, 4 * c);
        f.vis.resize(f.n); f.ref.resize(f.n);
        for (std::uint32_t i = 0; i < f.n; ++i) { rd(f.vis[i], c); rd(f.ref[i], c); }
        return f;
    }
    scene::Scene scene = scene::loadScene(GLINT_SOURCE_DIR "/harness/scenes/courtyard_penumbra.toml");
    scene.frameCount = frames;
    scene.width = W; scene.height = H;
    scene.reference.shadows = true;
    scene.reference.samplesPerPixel = 64;
    scene::Simulation sim = scene::simulate(test::testContext(), scene);
    f.w = sim.frames[0].width; f.h = sim.frames[0].height; f.n = frames;
    ShadowDenoiserDesc desc;
    replay::shadowDescFromFrame(sim.frames[0], 0, true, desc);
    const double nn = desc.nearPlane, ff = desc.farPlane;
    f.vd[0] = float(nn * ff / (ff - nn)); f.vd[1] = float(ff / (ff - nn)); f.vd[2] = -1.0f;
    for (std::uint32_t i = 0; i < frames; ++i) {
        gpu::ShadowInputs inputs = replay::shadowInputsFromFrame(sim.frames[i], {});
        f.vis.push_back(inputs.visibility);
        f.ref.push_back(replay::layerChannels(sim.frames[i], "reference.shadow", 1));
        if (i == 0) { f.depth = inputs.depth; f.normals = inputs.normals; }
    }
    std::ofstream out(path, std::ios::binary);
    out.write((char*)&f.w, 4); out.write((char*)&f.h, 4); out.write((char*)&f.n, 4); out.write((char*)f.vd, 12);
    out.write((char*)f.depth.data(), f.depth.size() * 4); out.write((char*)f.normals.data(), f.normals.size() * 4);
    for (std::uint32_t i = 0; i < f.n; ++i) {
        out.write((char*)f.vis[i].data(), f.vis[i].size() * 4);
        out.write((char*)f.ref[i].data(), f.ref[i].size() * 4);
    }
    return f;
}

double err(const std::vector<float>& v, std::size_t stride, const std::vector<float>& ref) {
    double s = 0; std::size_t c = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
        if (!(ref[i] > 0.05f && ref[i] < 0.95f)) continue;
        s += std::abs(double(v[i * stride]) - ref[i]); ++c;
    }
    return s / double(c);
}
double bias(const std::vector<float>& v, std::size_t stride, const std::vector<float>& ref) {
    double s = 0; std::size_t c = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
        if (!(ref[i] > 0.05f && ref[i] < 0.95f)) continue;
        s += double(v[i * stride]) - ref[i]; ++c;
    }
    return s / double(c);
}

struct Opt {
    const char* name = "baseline";
    bool remap = true;
    float clampK = 0.5f; // < 0: no clamp
    float alphaMin = 0.05f;
    int blend = 0;       // 0 FFX youth; 1: max(1/n, alphaMin)
    bool histFilter0 = true;
    int varMode = 0;     // 0: FFX; 1: var of the mean var_t/n (with spatial for young)
    bool damping = true;
    int passes = 3;
    float nCap = 1023.0f;
};

void runVariant(const Frames& F, const Opt& o, bool verbose) {
    const int w = int(F.w), h = int(F.h);
    const std::size_t count = std::size_t(w) * h;
    std::vector<float> moments(4 * count, 0.0f), hist(2 * count, 0.0f);
    std::vector<double> avg(count, 0.0);
    reference::ShadowFilterInputs fi;
    fi.width = F.w; fi.height = F.h; fi.depth = F.depth; fi.normals = F.normals;
    fi.viewDepth[0] = F.vd[0]; fi.viewDepth[1] = F.vd[1]; fi.viewDepth[2] = F.vd[2];
    std::printf("%-28s", o.name);
    double e0 = 0, eLast = 0;
    for (std::uint32_t fr = 0; fr < F.n; ++fr) {
        const std::vector<float>& vis = F.vis[fr];
        auto mask = reference::packShadowMask(vis, F.w, F.h);
        const int tX = (w + 7) / 8, tY = (h + 3) / 4;
        auto word = [&](int tx, int ty) { return mask[std::size_t(std::clamp(ty, 0, tY - 1)) * tX + std::clamp(tx, 0, tX - 1)]; };
        auto rowSum = [&](int x, int y) {
            const int row = std::clamp(y, 0, h - 1); const int sh = (row & 3) * 8;
            std::uint32_t l = (word((x >> 3) - 1, row >> 2) >> sh) & 0xFF, c = (word(x >> 3, row >> 2) >> sh) & 0xFF,
                          r = (word((x >> 3) + 1, row >> 2) >> sh) & 0xFF;
            std::uint32_t win = (l | (c << 8) | (r << 16)) >> (x & 7);
            float s = 0; for (int k = 0; k <= 16; ++k) if ((win >> k) & 1u) s += kG[std::abs(k - 8)];
            return s;
        };
        auto recv = [&](std::size_t i) { float d = F.depth[i]; return d > 1e-6f && d < 1 - 1e-6f; };
        std::vector<float> sv(2 * count, 0.0f), nm(4 * count, 0.0f);
        for (int gy = 0; gy < (h + 7) / 8; ++gy)
            for (int gx = 0; gx < tX; ++gx) {
                bool any = false;
                for (int y = gy * 8; y < std::min(gy * 8 + 8, h); ++y)
                    for (int x = gx * 8; x < std::min(gx * 8 + 8, w); ++x) any |= recv(std::size_t(y) * w + x);
                std::uint32_t om = 0, am = ~0u;
                for (int j = -2; j <= 3; ++j) for (int i = -1; i <= 1; ++i) { om |= word(gx + i, gy * 2 + j); am &= word(gx + i, gy * 2 + j); }
                const bool lit = am == ~0u, clear = !any || lit || om == 0u;
                for (int y = gy * 8; y < std::min(gy * 8 + 8, h); ++y)
                    for (int x = gx * 8; x < std::min(gx * 8 + 8, w); ++x) {
                        const std::size_t p = std::size_t(y) * w + x;
                        const bool rc = recv(p);
                        if (clear) { float v = any && lit && rc ? 1.f : 0.f; sv[2 * p] = v; nm[4 * p] = v; nm[4 * p + 2] = rc ? 1.f : 0.f; continue; }
                        if (!rc) continue;
                        float mu = 0; for (int r = -8; r <= 8; ++r) mu += kG[std::abs(r)] * rowSum(x, y + r);
                        mu = std::clamp(mu, 0.f, 1.f);
                        const float sVar = std::max(mu - mu * mu, 0.f), sSig = std::sqrt(sVar);
                        const float xs = ((word(x >> 3, y >> 2) >> ((y & 3) * 8 + (x & 7))) & 1u) ? 1.f : 0.f;
                        float m = 0, m2 = 0, cnt = 0, hv = mu;
                        if (fr > 0) { m = moments[4 * p]; m2 = moments[4 * p + 1]; cnt = std::min(moments[4 * p + 2], o.nCap); hv = hist[2 * p]; }
                        float n = cnt + 1;
                        const float d = xs - m, nmn = m + d / n, nm2 = m2 + d * (xs - nmn);
                        const float tVar = n > 1 ? nm2 / (n - 1) : 1.f;
                        const float rad = o.clampK * sSig;
                        const float cl = o.clampK < 0 ? hv : std::clamp(hv, mu - rad, mu + rad);
                        if (o.damping && o.clampK >= 0) { const float dv = (hv - mu) / std::max(rad, 0.001f); n *= std::exp(-dv * dv / 20.f); }
                        float var, res;
                        if (o.varMode == 0) var = n < 16 ? std::max(tVar, sVar) * std::max(16 - n, 1.f) : tVar;
                        else var = n < 16 ? std::max(tVar, sVar) * std::max(16 - n, 1.f) / n : tVar / n;
                        if (o.blend == 0) { const float youth = std::sqrt(std::max(8 - n, 0.f) / 8); res = cl + (xs - cl) * (o.alphaMin + (1 - o.alphaMin) * youth); }
                        else { const float a = std::max(1.f / n, o.alphaMin); res = cl + (xs - cl) * a; }
                        sv[2 * p] = std::clamp(res, 0.f, 1.f); sv[2 * p + 1] = std::max(var, 0.f);
                        nm[4 * p] = nmn; nm[4 * p + 1] = nm2; nm[4 * p + 2] = n;
                    }
            }
        moments = nm;
        std::vector<float> cur = sv;
        for (int ps = 0; ps < o.passes; ++ps) {
            cur = reference::shadowFilterPass(fi, cur, 1u << ps, ps == 2 && o.remap);
            if (ps == 0) hist = o.histFilter0 ? cur : sv;
        }
        if (o.passes == 0) hist = sv;
        for (std::size_t i = 0; i < count; ++i) avg[i] += vis[i];
        const double e = err(cur, 2, F.ref[fr]);
        if (fr == 0) e0 = e; eLast = e;
        if (verbose || fr % 4 == 3 || fr == 0) std::printf(" %2u:%.4f", fr, e);
        if (verbose) {
            std::vector<float> av(count); for (std::size_t i = 0; i < count; ++i) av[i] = float(avg[i] / (fr + 1));
            std::printf(" [cls %.4f b%+.4f | out b%+.4f | avg %.4f]\n", err(sv, 2, F.ref[fr]), bias(sv, 2, F.ref[fr]), bias(cur, 2, F.ref[fr]), err(av, 1, F.ref[fr]));
        }
    }
    std::vector<float> av(count); for (std::size_t i = 0; i < count; ++i) av[i] = float(avg[i] / F.n);
    std::printf("  | first %.4f last %.4f avg%u %.4f\n", e0, eLast, F.n, err(av, 1, F.ref[F.n - 1]));
    std::fflush(stdout);
}
} // namespace

TEST_CASE("experiment", "[experiment]") {
    const char* sz = std::getenv("EXP_SIZE");
    std::uint32_t W = 160, H = 90, N = 32;
    if (sz) std::sscanf(sz, "%ux%ux%u", &W, &H, &N);
    Frames F = load(N, W, H);
    std::vector<Opt> opts;
    opts.push_back(Opt{});
    { Opt o; o.name = "noremap"; o.remap = false; opts.push_back(o); }
    { Opt o; o.name = "noremap+hist=classify"; o.remap = false; o.histFilter0 = false; opts.push_back(o); }
    { Opt o; o.name = "noremap+noclamp"; o.remap = false; o.clampK = -1; opts.push_back(o); }
    { Opt o; o.name = "noremap+1/n(.05)"; o.remap = false; o.blend = 1; opts.push_back(o); }
    { Opt o; o.name = "noremap+1/n(.01)"; o.remap = false; o.blend = 1; o.alphaMin = 0.01f; opts.push_back(o); }
    { Opt o; o.name = "noremap+varmean"; o.remap = false; o.varMode = 1; opts.push_back(o); }
    { Opt o; o.name = "noremap+varmean+1/n+hcls"; o.remap = false; o.varMode = 1; o.blend = 1; o.alphaMin = 0.01f; o.histFilter0 = false; opts.push_back(o); }
    { Opt o; o.name = "nofilter"; o.remap = false; o.passes = 0; opts.push_back(o); }
    const char* only = std::getenv("EXP_VERBOSE");
    for (auto& o : opts) runVariant(F, o, only && std::string(only) == o.name);
}
