// glint_fuzz_make_corpus <corpus-dir>: writes the generated seeds of every fuzz target into
// <corpus-dir>/<target>/ (tests/fuzz/corpus in the repository, see its README.md): small
// valid files of every kind the readers take, every OpenEXR compression and tiling, the
// malformed cases of tests/capture, and the two hand-made files of issue 24 that made
// `glint info` allocate more than 2 GiB. Deterministic: running it again rewrites the same
// bytes.
#include "fuzz_support.h"

#include <capture/capture_error.h>
#include <capture/environment_io.h>
#include <capture/frame_io.h>
#include <capture/sample_frame.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfStringVectorAttribute.h>
#include <OpenEXR/ImfTiledOutputFile.h>

#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace glint;

namespace {
std::string readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void put32(std::string& b, std::size_t at, std::uint32_t v) {
    for (std::size_t i = 0; i < 4; ++i) b[at + i] = static_cast<char>((v >> (8 * i)) & 0xff);
}
std::string bytes32(std::uint32_t v) {
    std::string b(4, '\0');
    put32(b, 0, v);
    return b;
}
std::string bytes64(std::uint64_t v) {
    return bytes32(static_cast<std::uint32_t>(v)) + bytes32(static_cast<std::uint32_t>(v >> 32));
}

// Every channel of `source` read as float and written again with `header`'s settings.
void rewrite(const fs::path& source, const fs::path& target, Imf::Compression compression,
             const Imf::TileDescription* tiles = nullptr) {
    Imf::InputFile in(source.c_str());
    Imf::Header header = in.header();
    header.compression() = compression;
    const Imath::Box2i dw = header.dataWindow();
    const int width = dw.max.x + 1, height = dw.max.y + 1;
    // Samples stay in their file type (OutputFile does not convert), 4 bytes each at most.
    std::vector<std::vector<float>> planes;
    Imf::FrameBuffer buffer;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        const Imf::PixelType type = it.channel().type;
        const std::size_t bytes = type == Imf::HALF ? 2 : 4;
        std::vector<float>& plane =
            planes.emplace_back(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
        buffer.insert(it.name(), Imf::Slice(type, reinterpret_cast<char*>(plane.data()), bytes,
                                            bytes * static_cast<std::size_t>(width)));
    }
    in.setFrameBuffer(buffer);
    in.readPixels(0, height - 1);
    if (tiles) {
        header.setTileDescription(*tiles);
        Imf::TiledOutputFile out(target.c_str(), header);
        out.setFrameBuffer(buffer);
        for (int level = 0; level < out.numLevels(); ++level)
            out.writeTiles(0, out.numXTiles(level) - 1, 0, out.numYTiles(level) - 1, level, level);
        // Only level 0 holds the image; the smaller levels are written from the same buffer
        // (OpenEXR reads each from its own window, which all start at the origin).
    } else {
        Imf::OutputFile out(target.c_str(), header);
        out.setFrameBuffer(buffer);
        out.writePixels(height);
    }
}

void writeHeaderOnly(const fs::path& file, const Imf::Header& header) {
    Imf::StdOFStream out(file.c_str());
    const char preamble[8] = {0x76, 0x2f, 0x31, 0x01, 0x02, 0x00, 0x00, 0x00};
    out.write(preamble, 8);
    header.writeTo(out);
}

// The size field of attribute `name` in a single-part file written by OpenEXR.
std::size_t attributeSizeAt(const std::string& b, const std::string& name) {
    const std::size_t at = b.find(name + std::string(1, '\0'));
    if (at == std::string::npos) throw std::runtime_error("no attribute " + name);
    const std::size_t type = at + name.size() + 1;
    return b.find('\0', type) + 1;
}

void frameSeeds(const fs::path& dir, const fs::path& scratch) {
    fs::create_directories(dir);
    const fs::path sample = dir / "sample_16x12_zip.exr";
    capture::writeFrame(sample, capture::makeSampleFrame(16, 12, 0));
    // Three ZIP chunks of 16 scanlines (the 16x12 sample has one), still small.
    capture::writeFrame(dir / "sample_24x40_zip.exr", capture::makeSampleFrame(24, 40, 1));
    const std::vector<std::pair<Imf::Compression, const char*>> compressions{
        {Imf::NO_COMPRESSION, "none"},   {Imf::RLE_COMPRESSION, "rle"},     {Imf::ZIPS_COMPRESSION, "zips"},
        {Imf::PIZ_COMPRESSION, "piz"},   {Imf::PXR24_COMPRESSION, "pxr24"}, {Imf::B44_COMPRESSION, "b44"},
        {Imf::B44A_COMPRESSION, "b44a"}, {Imf::DWAA_COMPRESSION, "dwaa"},   {Imf::DWAB_COMPRESSION, "dwab"}};
    for (const auto& [compression, name] : compressions)
        rewrite(sample, dir / (std::string("sample_16x12_") + name + ".exr"), compression);
    const Imf::TileDescription oneLevel(8, 8, Imf::ONE_LEVEL);
    rewrite(sample, dir / "sample_16x12_tiled.exr", Imf::ZIP_COMPRESSION, &oneLevel);
    const Imf::TileDescription mipmap(8, 4, Imf::MIPMAP_LEVELS, Imf::ROUND_UP);
    rewrite(sample, dir / "sample_16x12_mipmap.exr", Imf::NO_COMPRESSION, &mipmap);
    capture::writeEnvironment(dir / "environment_16x8.exr", capture::makeSampleEnvironment(16, 8));

    const std::string good = readBytes(sample);
    fuzz::writeText(dir / "malformed_truncated_half.exr", good.substr(0, good.size() / 2));
    fuzz::writeText(dir / "malformed_truncated_header.exr", good.substr(0, 300));
    std::string corrupt = good;
    for (std::size_t i = good.size() / 2; i < good.size() / 2 + 8; ++i)
        corrupt[i] = static_cast<char>(~corrupt[i]);
    fuzz::writeText(dir / "malformed_corrupt_pixels.exr", corrupt);
    Imf::Header plain(8, 8);
    plain.channels().insert("R", Imf::Channel(Imf::HALF));
    {
        Imf::OutputFile out((dir / "malformed_plain_exr.exr").c_str(), plain);
        out.setFrameBuffer(Imf::FrameBuffer{});
        out.writePixels(8);
    }

    // Issue 24 (a): a string attribute whose size field says 0x7fffffff, in a few-KB frame.
    Imf::Header header = Imf::InputFile(sample.c_str()).header();
    header.insert("glint.comment", Imf::StringAttribute("a short note"));
    const fs::path withNote = scratch / "note.exr";
    {
        Imf::OutputFile out(withNote.c_str(), header);
        out.setFrameBuffer(Imf::FrameBuffer{});
        out.writePixels(12);
    }
    std::string note = readBytes(withNote);
    put32(note, attributeSizeAt(note, "glint.comment"), 0x7fffffffu);
    fuzz::writeText(dir / "issue24_string_size_0x7fffffff.exr", note);

    // Issue 24 (b): 8192x8192 with 8 channels and no pixel data: the header alone, and the
    // header with an offset table and 512 four-byte ZIP chunks.
    Imf::Header big = Imf::InputFile(sample.c_str()).header();
    big.dataWindow() = Imath::Box2i({0, 0}, {8191, 8191});
    big.displayWindow() = big.dataWindow();
    big.channels() = Imf::ChannelList();
    big.channels().insert("depth.Z", Imf::Channel(Imf::FLOAT));
    for (const char* c : {"color.R", "color.G", "color.B", "color.A"})
        big.channels().insert(c, Imf::Channel(Imf::HALF));
    for (const char* c : {"normal.X", "normal.Y", "normal.Z"})
        big.channels().insert(c, Imf::Channel(Imf::FLOAT));
    big.insert("glint.effects", Imf::StringVectorAttribute({"depth_pyramid"}));
    big.insert("glint.roughnessSource", Imf::StringAttribute(""));
    writeHeaderOnly(dir / "issue24_8192x8192x8_header_only.exr", big);
    std::string starved = readBytes(dir / "issue24_8192x8192x8_header_only.exr");
    const std::uint64_t dataStart = starved.size() + 8 * 512;
    for (std::uint32_t i = 0; i < 512; ++i) starved += bytes64(dataStart + std::uint64_t{i} * 12);
    for (std::uint32_t i = 0; i < 512; ++i)
        starved += bytes32(16 * i) + bytes32(4) + std::string("\x78\x9c\x03\x00", 4);
    fuzz::writeText(dir / "issue24_8192x8192x8_starved_chunks.exr", starved);
}

void manifestSeeds(const fs::path& dir, const fs::path& scratch) {
    fs::create_directories(dir);
    fuzz::writeSampleSequence(scratch / "sequence");
    fs::copy_file(scratch / "sequence" / "manifest.json", dir / "sample.json",
                  fs::copy_options::overwrite_existing);
    const std::vector<std::pair<const char*, const char*>> manifests{
        {"no_environment.json",
         R"({"format": "glint-sequence", "version": 1, "frames": ["frame_0000.exr", "frame_0001.exr"], "frameRate": 30})"},
        {"one_frame.json",
         R"({"format":"glint-sequence","version":1,"frames":["frame_0001.exr"],"frameRate":24.5,"environment":"environment.exr"})"},
        {"listed_twice.json",
         R"({"format":"glint-sequence","version":1,"frames":["frame_0000.exr","frame_0000.exr"],"frameRate":30})"},
        {"outside_folder.json",
         R"({"format":"glint-sequence","version":1,"frames":["../frame_0000.exr"],"frameRate":30})"},
        {"environment_as_frame.json",
         R"({"format":"glint-sequence","version":1,"frames":["environment.exr"],"frameRate":30})"},
        {"bad_version.json",
         R"({"format":"glint-sequence","version":2.5,"frames":["frame_0000.exr"],"frameRate":1e400})"},
        {"wrong_types.json",
         R"({"format":["glint-sequence"],"version":"1","frames":{"a":1},"frameRate":-1})"},
        {"truncated.json", R"({"format":"glint-sequence","version":1,"frames":["frame_0000.e)"},
    };
    for (const auto& [name, text] : manifests) fuzz::writeText(dir / name, text);
}

void copyAll(const fs::path& from, const std::string& extension, const fs::path& to) {
    fs::create_directories(to);
    for (const auto& entry : fs::directory_iterator(from))
        if (entry.path().extension() == extension)
            fs::copy_file(entry.path(), to / entry.path().filename(), fs::copy_options::overwrite_existing);
}

void sceneSeeds(const fs::path& dir) {
    copyAll(fs::path(GLINT_SOURCE_DIR) / "harness" / "scenes", ".toml", dir);
    const std::vector<std::pair<const char*, const char*>> scenes{
        {"every_section.toml", R"(effects = ["reflections", "shadows"]
resolution = [64, 32]
frames = 3
seed = 9
shadow_samples = 4
shadow_light = 0
[camera]
position = [0, 2, 4]
target = [0, 0, 0]
fov_y = 60
depth = "reversed"
[[camera.keyframes]]
frame = 0
[[camera.keyframes]]
frame = 2
position = [1, 2, 4]
[environment]
type = "sky"
resolution = [64, 32]
[[lights]]
type = "sphere"
position = [0, 3, 0]
radius = 0.2
[[lights.keyframes]]
frame = 0
[[lights.keyframes]]
frame = 2
position = [1, 3, 0]
[materials.m]
roughness_ramp = { start = [-1, 0, 0], end = [1, 0, 0], from = 0.0, to = 1.0 }
[[objects]]
type = "sphere"
material = "m"
radius = 0.5
[[objects.keyframes]]
frame = 1
rotation = [0, 90, 0]
[reference]
reflections = true
shadows = true
spp = 4
)"},
        {"matrices.toml", R"(effects = ["hybrid"]
[camera]
view = [1,0,0,0, 0,1,0,0, 0,0,1,-5, 0,0,0,1]
projection = [1,0,0,0, 0,1,0,0, 0,0,0,0.1, 0,0,-1,0]
depth = "reversed_infinite"
ndc_y_down = true
[materials.m]
[[objects]]
type = "box"
material = "m"
size = [1, 2, 3]
)"},
        {"mesh_missing.toml", "effects = [\"reflections\"]\n[materials.m]\n[[objects]]\ntype = \"mesh\"\n"
                              "material = \"m\"\nfile = \"model.glb\"\nfit_size = 2\n"},
        {"syntax_error.toml", "effects = [\"shadows\"\n[[lights]]\ntype = \"directional\"\n"},
        {"unknown_key.toml",
         "effects = [\"shadows\"]\n[[lights]]\ntype = \"directional\"\ncolour = [1, 1, 1]\n"},
    };
    for (const auto& [name, text] : scenes) fuzz::writeText(dir / name, text);
}

// A triangle and a two-node box, base64 buffers inside, and the same triangle as .glb.
void gltfSeeds(const fs::path& dir) {
    fs::create_directories(dir);
    // Three float3 positions (0,0,0), (1,0,0), (0,1,0) = 36 bytes.
    const char* triangleBuffer = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";
    const std::string triangle = std::string(R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
"nodes":[{"mesh":0,"translation":[0,1,0]}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],
"bufferViews":[{"buffer":0,"byteLength":36}],
"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,)") +
                                 triangleBuffer + "\"}]}\n";
    fuzz::writeText(dir / "triangle.gltf", triangle);
    const std::string indexed = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
"nodes":[{"children":[1],"scale":[2,2,2]},{"mesh":0,"rotation":[0,0.7071068,0,0.7071068]}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"mode":4}]}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
{"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}],
"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],
"buffers":[{"byteLength":44,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="}]}
)";
    fuzz::writeText(dir / "indexed_nodes.gltf", indexed);
    // .glb: 12-byte header, a JSON chunk and a BIN chunk, each 4-byte aligned.
    std::string json =
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],)"
        R"("bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36}]})";
    while (json.size() % 4) json += ' ';
    std::string bin;
    for (float v : {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f}) {
        std::uint32_t u = 0;
        std::memcpy(&u, &v, 4);
        bin += bytes32(u);
    }
    const std::uint32_t total = static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size());
    const std::string glb = "glTF" + bytes32(2) + bytes32(total) +
                            bytes32(static_cast<std::uint32_t>(json.size())) + "JSON" + json +
                            bytes32(static_cast<std::uint32_t>(bin.size())) + std::string("BIN\0", 4) + bin;
    fuzz::writeText(dir / "triangle.glb", glb);
}

void channelMapSeeds(const fs::path& dir) {
    fs::create_directories(dir);
    fs::copy_file(fuzz::blenderMapPath(), dir / "blender.toml", fs::copy_options::overwrite_existing);
    fuzz::writeText(dir / "header_camera.toml", fuzz::headerCameraMap());
    const std::vector<std::pair<const char*, const char*>> maps{
        {"folders.toml", R"(version = 1
effects = ["shadows"]
flip_vertical = true
[depth]
channel = "depth.exr:R"
kind = "device"
[normal]
channels = ["normal.exr:R", "normal.exr:G"]
space = "view"
encoding = "octahedral"
[motion]
channels = ["motion.exr:R", "motion.exr:G"]
units = "ndc"
scale = [0.5, -0.5]
direction = "from_previous"
[shadow]
channel = "shadow.exr:R"
[camera]
file = "cameras.json"
depth_convention = "reversed_infinite"
ndc_y_down = true
)"},
        {"everything.toml", R"(version = 1
effects = ["reflections", "depth_pyramid"]
environment = "sky.exr"
[world]
axes = ["-x", "z", "y"]
[color]
channels = ["ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B"]
[depth]
channel = "ViewLayer.Depth.Z"
kind = "view_z"
background_from = 1e9
[normal]
channels = ["ViewLayer.Normal.X", "ViewLayer.Normal.Y", "ViewLayer.Normal.Z"]
space = "world"
encoding = "unorm"
[roughness]
channel = "ViewLayer.roughness.X"
convention = "alpha"
[motion]
channels = ["ViewLayer.Vector.X", "ViewLayer.Vector.Y"]
units = "uv"
y_up = true
[reference.reflection]
channels = ["ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B"]
[reference.shadow]
channel = "ViewLayer.Combined.A"
[material]
base_color = ["ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B"]
metallic = "ViewLayer.roughness.X"
[camera]
source = "side_file"
depth_convention = "standard"
)"},
        {"unknown_key.toml", "version = 1\neffects = [\"depth_pyramid\"]\n[depth]\nchannel = \"Z\"\nknd = "
                             "\"view_z\"\n[camera]\n"},
        {"bad_version.toml", "version = 2\neffects = []\n"},
        {"syntax_error.toml", "version = 1\neffects = [\"depth_pyramid\"\n"},
    };
    for (const auto& [name, text] : maps) fuzz::writeText(dir / name, text);
}

void mappedFrameSeeds(const fs::path& dir, const fs::path& frameCorpus) {
    fs::create_directories(dir);
    const fs::path capture = dir.parent_path() / ".capture";
    fuzz::writeBlenderCapture(capture);
    fs::copy_file(capture / "0001.exr", dir / "blender_0001.exr", fs::copy_options::overwrite_existing);
    fs::copy_file(capture / "0002.exr", dir / "blender_0002.exr", fs::copy_options::overwrite_existing);
    rewrite(capture / "0002.exr", dir / "blender_0002_piz.exr", Imf::PIZ_COMPRESSION);
    const Imf::TileDescription tiles(8, 8, Imf::ONE_LEVEL);
    rewrite(capture / "0002.exr", dir / "blender_0002_tiled.exr", Imf::RLE_COMPRESSION, &tiles);
    const std::string good = readBytes(capture / "0002.exr");
    fuzz::writeText(dir / "blender_0002_truncated.exr", good.substr(0, good.size() * 3 / 4));
    for (const char* name : {"issue24_string_size_0x7fffffff.exr", "issue24_8192x8192x8_starved_chunks.exr"})
        fs::copy_file(frameCorpus / name, dir / name, fs::copy_options::overwrite_existing);
    fs::remove_all(capture);
}

void cameraFileSeeds(const fs::path& dir) {
    fs::create_directories(dir);
    fuzz::writeText(dir / "blender.json", fuzz::blenderCameraJson());
    const std::vector<std::pair<const char*, const char*>> cameras{
        {"positional_rows.json", R"({"vectors": "row", "frames": [
 {"view": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,-5,1]], "fov_y_degrees": 40, "near": 0.1, "far": 50},
 {"view": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0.5,-5,1]], "fov_y_degrees": 40, "near": 0.1, "far": 50,
  "prev_view_projection": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}]})"},
        {"projections.json", R"({"format": "glint-camera", "version": 1, "vectors": "column", "frames": [
 {"file": "0001.exr", "view": [1,0,0,0, 0,1,0,0, 0,0,1,-5, 0,0,0,1],
  "projection_gl": [1.5,0,0,0, 0,2,0,0, 0,0,-1.002,-0.2002, 0,0,-1,0], "near": 0.1, "far": 100},
 {"file": "0002.exr", "view": [1,0,0,0, 0,1,0,0, 0,0,1,-5, 0,0,0,1],
  "projection": [1.5,0,0,0, 0,2,0,0, 0,0,0.001,0.1, 0,0,-1,0], "near": 0.1, "far": 100}]})"},
        {"orthographic.json", R"({"frames": [{"view": [1,0,0,0, 0,1,0,0, 0,0,1,-5, 0,0,0,1],
  "projection_gl": [0.1,0,0,0, 0,0.1,0,0, 0,0,-0.02,-1, 0,0,0,1], "near": 1, "far": 100}]})"},
        {"missing_far.json",
         R"({"frames": [{"file": "0002.exr", "view": [1,0,0,0], "fov_y_degrees": 200}]})"},
        {"unknown_key.json", R"({"format": "glint-camera", "frames": [], "fov": 1})"},
        {"not_json.json", "frames = [1, 2]\n"},
    };
    for (const auto& [name, text] : cameras) fuzz::writeText(dir / name, text);
}
} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: glint_fuzz_make_corpus <corpus-dir>\n");
        return 2;
    }
    try {
        const fs::path root = argv[1];
        const fs::path scratch = fuzz::scratchDir();
        frameSeeds(root / "frame", scratch);
        manifestSeeds(root / "manifest", scratch);
        sceneSeeds(root / "scene");
        gltfSeeds(root / "gltf");
        channelMapSeeds(root / "channel_map");
        mappedFrameSeeds(root / "mapped_frame", root / "frame");
        cameraFileSeeds(root / "camera_file");
        std::printf("wrote the generated seeds under %s\n", root.string().c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint_fuzz_make_corpus: %s\n", e.what());
        return 1;
    }
}
