// Loading channel maps (TOML) and listing the frames of a mapped capture.
#include "capture/channel_map.h"

#include "capture/capture_error.h"
#include "capture/frame_validation.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <string_view>

namespace glint::capture {

namespace {
constexpr std::int64_t kMapVersion = 1;

// Reads one table of the map, naming the file, the line and the full key in every message.
struct MapReader {
    const std::string& file;

    [[noreturn]] void fail(const toml::node* node, const std::string& key, const std::string& problem) const {
        std::string where = file;
        if (node && node->source().begin.line > 0) where += ":" + std::to_string(node->source().begin.line);
        throw CaptureError(where, key + ": " + problem);
    }

    static std::string join(const std::string& prefix, std::string_view key) {
        return prefix.empty() ? std::string(key) : prefix + "." + std::string(key);
    }

    // A misspelt key silently ignored would be a map that lies about the capture.
    void onlyKeys(const toml::table& t, const std::string& prefix,
                  std::initializer_list<std::string_view> allowed) const {
        for (const auto& [key, node] : t) {
            if (std::find(allowed.begin(), allowed.end(), key.str()) == allowed.end())
                fail(&node, join(prefix, key.str()), "unknown key");
        }
    }

    const toml::table* table(const toml::table& t, const std::string& prefix, const char* key) const {
        const toml::node* node = t.get(key);
        if (!node) return nullptr;
        if (!node->is_table())
            fail(node, join(prefix, key), "expected a table ([" + join(prefix, key) + "])");
        return node->as_table();
    }

    std::string text(const toml::table& t, const std::string& prefix, const char* key, bool required,
                     const std::string& fallback = {}) const {
        const toml::node* node = t.get(key);
        if (!node) {
            if (required) fail(&t, join(prefix, key), "missing (required)");
            return fallback;
        }
        std::optional<std::string> value = node->value_exact<std::string>();
        if (!value || value->empty()) fail(node, join(prefix, key), "expected a non-empty string");
        return *value;
    }

    // One of `names`; returns its index.
    std::size_t choice(const toml::table& t, const std::string& prefix, const char* key,
                       std::initializer_list<std::string_view> names, std::size_t fallback) const {
        const toml::node* node = t.get(key);
        if (!node) return fallback;
        const std::string value = text(t, prefix, key, true);
        std::size_t i = 0;
        std::string list;
        for (std::string_view name : names) {
            if (name == value) return i;
            list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + std::string(name);
            ++i;
        }
        fail(node, join(prefix, key), "unknown value '" + value + "' (expected " + list + ")");
    }

    std::vector<std::string> texts(const toml::table& t, const std::string& prefix, const char* key,
                                   std::size_t minCount, std::size_t maxCount) const {
        const toml::node* node = t.get(key);
        if (!node) fail(&t, join(prefix, key), "missing (required)");
        const toml::array* array = node->as_array();
        const std::string counts = minCount == maxCount
                                       ? std::to_string(minCount)
                                       : std::to_string(minCount) + " to " + std::to_string(maxCount);
        if (!array || array->size() < minCount || array->size() > maxCount)
            fail(node, join(prefix, key), "expected an array of " + counts + " strings");
        std::vector<std::string> out;
        for (const toml::node& element : *array) {
            std::optional<std::string> value = element.value_exact<std::string>();
            if (!value || value->empty()) fail(&element, join(prefix, key), "expected non-empty strings");
            out.push_back(*value);
        }
        return out;
    }

    double number(const toml::table& t, const std::string& prefix, const char* key, double fallback) const {
        const toml::node* node = t.get(key);
        if (!node) return fallback;
        std::optional<double> value = node->value<double>();
        if (!value || !std::isfinite(*value)) fail(node, join(prefix, key), "expected a finite number");
        return *value;
    }

    bool flag(const toml::table& t, const std::string& prefix, const char* key, bool fallback) const {
        const toml::node* node = t.get(key);
        if (!node) return fallback;
        std::optional<bool> value = node->value_exact<bool>();
        if (!value) fail(node, join(prefix, key), "expected true or false");
        return *value;
    }

    AxisMap axes(const toml::table& t, const std::string& prefix, const char* key) const {
        if (!t.get(key)) return {};
        const std::vector<std::string> names = texts(t, prefix, key, 3, 3);
        AxisMap map;
        std::array<bool, 3> used{};
        for (std::size_t i = 0; i < 3; ++i) {
            std::string_view name = names[i];
            map.sign[i] = 1.0;
            if (!name.empty() && (name[0] == '-' || name[0] == '+')) {
                map.sign[i] = name[0] == '-' ? -1.0 : 1.0;
                name.remove_prefix(1);
            }
            const int axis = name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : -1;
            if (axis < 0 || used[static_cast<std::size_t>(axis)])
                fail(t.get(key), join(prefix, key),
                     "expected a permutation of x, y, z with optional signs, e.g. [\"x\", \"z\", \"-y\"]");
            used[static_cast<std::size_t>(axis)] = true;
            map.axis[i] = axis;
        }
        return map;
    }

    // One signed axis name: "x", "-y", "+z".
    AxisDirection direction(const toml::table& t, const std::string& prefix, const char* key,
                            AxisDirection fallback) const {
        if (!t.get(key)) return fallback;
        const std::string value = text(t, prefix, key, true);
        std::string_view name = value;
        AxisDirection d;
        if (name[0] == '-' || name[0] == '+') {
            d.sign = name[0] == '-' ? -1.0 : 1.0;
            name.remove_prefix(1);
        }
        d.axis = name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : -1;
        if (d.axis < 0) fail(t.get(key), join(prefix, key), "expected an axis name such as \"x\" or \"-y\"");
        return d;
    }
};

DepthConvention depthConventionOf(std::size_t i) {
    constexpr std::array<DepthConvention, 3> kAll{DepthConvention::Standard, DepthConvention::Reversed,
                                                  DepthConvention::ReversedInfinite};
    return kAll[i];
}

void readCamera(const MapReader& r, const toml::table& t, CameraMapping& c) {
    const std::string p = "camera";
    r.onlyKeys(t, p,
               {"source", "file", "depth_convention", "ndc_y_down", "view_attribute", "view_space",
                "fov_y_degrees", "fov_y_attribute", "near", "near_attribute", "far", "far_attribute"});
    c.source = r.choice(t, p, "source", {"side_file", "header"}, 0) == 0 ? CameraSource::SideFile
                                                                         : CameraSource::Header;
    c.depth = depthConventionOf(
        r.choice(t, p, "depth_convention", {"standard", "reversed", "reversed_infinite"}, 0));
    c.ndcYDown = r.flag(t, p, "ndc_y_down", false);
    if (c.source == CameraSource::SideFile) {
        for (const char* key : {"view_attribute", "view_space", "fov_y_degrees", "fov_y_attribute", "near",
                                "near_attribute", "far", "far_attribute"})
            if (t.get(key)) r.fail(t.get(key), p + "." + key, "only for source = \"header\"");
        c.file = r.text(t, p, "file", false, c.file);
        return;
    }
    if (t.get("file")) r.fail(t.get("file"), p + ".file", "only for source = \"side_file\"");
    c.viewAttribute = r.text(t, p, "view_attribute", true);
    c.viewSpace = r.choice(t, p, "view_space", {"openexr", "opengl"}, 0) == 0 ? HeaderViewSpace::OpenExr
                                                                              : HeaderViewSpace::OpenGl;
    // Each quantity comes from an attribute or a fixed number, exactly one of the two.
    auto either = [&](const char* attribute, const char* fixed, std::string& name, double& value,
                      bool required) {
        name = r.text(t, p, attribute, false);
        value = r.number(t, p, fixed, 0.0);
        if (!name.empty() && t.get(fixed))
            r.fail(t.get(fixed), p + "." + fixed, std::string("give either ") + fixed + " or " + attribute);
        if (required && name.empty() && !t.get(fixed))
            r.fail(&t, p + "." + fixed, std::string("missing (give ") + fixed + " or " + attribute + ")");
    };
    either("fov_y_attribute", "fov_y_degrees", c.fovYAttribute, c.fovYDegrees, true);
    either("near_attribute", "near", c.nearAttribute, c.nearZ, true);
    either("far_attribute", "far", c.farAttribute, c.farZ, c.depth != DepthConvention::ReversedInfinite);
    if (c.fovYAttribute.empty() && !(c.fovYDegrees > 0.0 && c.fovYDegrees < 180.0))
        r.fail(t.get("fov_y_degrees"), p + ".fov_y_degrees", "expected a value in (0, 180)");
    if (c.nearAttribute.empty() && !(c.nearZ > 0.0)) r.fail(t.get("near"), p + ".near", "expected > 0");
}

void readMotion(const MapReader& r, const toml::table& t, MotionMapping& m) {
    const std::string p = "motion";
    r.onlyKeys(t, p, {"channels", "units", "direction", "scale", "y_up", "background"});
    m.channels = r.texts(t, p, "channels", 2, 2);
    constexpr std::array<MotionUnits, 3> kUnits{MotionUnits::Pixels, MotionUnits::Uv, MotionUnits::Ndc};
    m.units = kUnits[r.choice(t, p, "units", {"pixels", "uv", "ndc"}, 1)];
    m.direction = r.choice(t, p, "direction", {"to_previous", "from_previous"}, 0) == 0
                      ? MotionDirection::ToPrevious
                      : MotionDirection::FromPrevious;
    if (const toml::node* node = t.get("scale")) {
        const toml::array* array = node->as_array();
        std::array<double, 2> s{};
        for (std::size_t i = 0; array && array->size() == 2 && i < 2; ++i)
            s[i] = (*array)[i].value<double>().value_or(0.0);
        if (!array || array->size() != 2 || !std::isfinite(s[0]) || !std::isfinite(s[1]) || s[0] == 0.0 ||
            s[1] == 0.0)
            r.fail(node, "motion.scale", "expected [x, y], finite and non-zero");
        m.scale = {static_cast<float>(s[0]), static_cast<float>(s[1])};
    }
    m.yUp = r.flag(t, p, "y_up", false);
    if (m.yUp && m.units == MotionUnits::Ndc)
        r.fail(t.get("y_up"), "motion.y_up",
               "not for units = \"ndc\" (its y direction is camera.ndc_y_down)");
    m.background = r.choice(t, p, "background", {"keep", "camera"}, 0) == 0 ? BackgroundMotion::Keep
                                                                            : BackgroundMotion::Camera;
}

// The source direction that [world] axes turns into glint's axis `i` (glint i = sign · source).
AxisDirection sourceAxisOf(const AxisMap& world, std::size_t i) {
    return {world.axis[i], world.sign[i]};
}

// `environment = "sky.exr"` (a glint environment map in glint's axes) or an [environment] table.
void readEnvironmentMapping(const MapReader& r, const toml::table& root, ChannelMap& map) {
    EnvironmentMapping& e = map.environment;
    e.center = sourceAxisOf(map.worldAxes, 2);
    e.up = sourceAxisOf(map.worldAxes, 1);
    const toml::node* node = root.get("environment");
    if (!node) return;
    if (!node->is_table()) {
        e.file = r.text(root, "", "environment", true);
        return;
    }
    const toml::table& t = *node->as_table();
    const std::string p = "environment";
    r.onlyKeys(t, p, {"file", "optional", "center"});
    e.file = r.text(t, p, "file", true);
    e.optional = r.flag(t, p, "optional", false);
    e.center = r.direction(t, p, "center", e.center);
    // The file's top row is the source's up, the axis that becomes glint's +y.
    if (e.center.axis == e.up.axis)
        r.fail(
            t.get("center"), "environment.center",
            "must be horizontal: perpendicular to the source axis that [world] axes turns into glint's +y");
}

// Which map sections each effect needs (the layers of docs/capture-format.md, "Required layers").
void checkEffects(const MapReader& r, const toml::table& root, const ChannelMap& map) {
    for (const std::string& effect : map.effects) {
        std::vector<std::pair<const char*, bool>> needs{{"depth", map.depth.has_value()}};
        if (effect == "reflections")
            needs.insert(needs.end(), {{"color", !map.color.empty()},
                                       {"normal", map.normal.has_value()},
                                       {"roughness", map.roughness.has_value()},
                                       {"motion", map.motion.has_value()}});
        if (effect == "shadows")
            needs.insert(needs.end(), {{"normal", map.normal.has_value()},
                                       {"motion", map.motion.has_value()},
                                       {"shadow", !map.shadow.empty()}});
        for (const auto& [section, present] : needs)
            if (!present)
                r.fail(root.get("effects"), "effects",
                       "effect '" + effect + "' needs a [" + section + "] section, which the map lacks");
    }
}

// Every source reference names a file ("depth.exr:R") or none does: a frame is either one
// file or one folder of files.
void checkReferences(const MapReader& r, const toml::table& root, ChannelMap& map) {
    std::vector<const std::string*> refs;
    auto add = [&](const std::vector<std::string>& names) {
        for (const std::string& n : names) refs.push_back(&n);
    };
    add(map.color);
    add(map.referenceReflection);
    add(map.baseColor);
    if (map.depth) refs.push_back(&map.depth->channel);
    if (map.normal) add(map.normal->channels);
    if (map.roughness) refs.push_back(&map.roughness->channel);
    if (map.motion) add(map.motion->channels);
    for (const std::string* s : {&map.shadow, &map.referenceShadow, &map.metallic})
        if (!s->empty()) refs.push_back(s);
    std::size_t qualified = 0;
    for (const std::string* ref : refs) {
        const ChannelRef split = splitChannelRef(*ref);
        if (split.file.empty()) continue;
        ++qualified;
        const std::filesystem::path file(split.file);
        const bool escapes =
            std::any_of(file.begin(), file.end(), [](const auto& part) { return part == ".."; });
        if (file.is_absolute() || escapes)
            r.fail(&root, "'" + *ref + "'",
                   "a texture file must be a relative path inside the frame's folder");
    }
    if (qualified != 0 && qualified != refs.size())
        r.fail(&root, "channels",
               "either every channel names its file (\"depth.exr:R\", one folder per frame) or none does");
    map.framesAreFolders = qualified != 0;
    if (map.framesAreFolders && map.camera.source == CameraSource::Header)
        r.fail(&root, "camera.source",
               "\"header\" needs single-file frames (this map reads a folder per frame)");
}

ChannelMap parseMap(const toml::table& root, const std::string& file) {
    const MapReader r{file};
    r.onlyKeys(root, "",
               {"version", "effects", "frames", "flip_vertical", "environment", "world", "color", "depth",
                "normal", "roughness", "motion", "shadow", "reference", "material", "camera"});
    const toml::node* version = root.get("version");
    if (!version) r.fail(&root, "version", "missing (required; this reader knows version 1)");
    if (version->value_exact<std::int64_t>() != kMapVersion)
        r.fail(version, "version", "unsupported (this reader knows version 1)");

    ChannelMap map;
    map.path = file;
    map.effects = r.texts(root, "", "effects", 1, 4);
    for (const std::string& effect : map.effects) {
        if (!isKnownEffect(effect))
            r.fail(root.get("effects"), "effects",
                   "unknown effect '" + effect + "' (known: reflections, hybrid, shadows, depth_pyramid)");
        if (std::count(map.effects.begin(), map.effects.end(), effect) > 1)
            r.fail(root.get("effects"), "effects", "effect '" + effect + "' is listed twice");
    }
    if (const toml::node* frames = root.get("frames")) {
        if (frames->is_array())
            map.frames = r.texts(root, "", "frames", 1, 100000);
        else
            map.frames = {r.text(root, "", "frames", true)};
        for (const std::string& pattern : map.frames)
            if (pattern.find_first_of("/\\") != std::string::npos)
                r.fail(frames, "frames",
                       "'" + pattern + "' is a path; give file (or folder) names, without folders");
    }
    map.flipVertical = r.flag(root, "", "flip_vertical", false);
    if (const toml::table* t = r.table(root, "", "world")) {
        r.onlyKeys(*t, "world", {"axes"});
        map.worldAxes = r.axes(*t, "world", "axes");
    }
    readEnvironmentMapping(r, root, map);
    if (const toml::table* t = r.table(root, "", "color")) {
        r.onlyKeys(*t, "color", {"channels"});
        map.color = r.texts(*t, "color", "channels", 3, 4);
    }
    if (const toml::table* t = r.table(root, "", "depth")) {
        r.onlyKeys(*t, "depth", {"channel", "kind", "background_from"});
        DepthMapping& d = map.depth.emplace();
        d.channel = r.text(*t, "depth", "channel", true);
        constexpr std::array<DepthKind, 3> kKinds{DepthKind::Device, DepthKind::ViewZ, DepthKind::Distance};
        d.kind = kKinds[r.choice(*t, "depth", "kind", {"device", "view_z", "distance"}, 0)];
        d.backgroundFrom = r.number(*t, "depth", "background_from", d.backgroundFrom);
        if (!(d.backgroundFrom > 0.0))
            r.fail(t->get("background_from"), "depth.background_from", "expected > 0");
        if (t->get("background_from") && d.kind == DepthKind::Device)
            r.fail(t->get("background_from"), "depth.background_from", "only for linear depth kinds");
    }
    if (const toml::table* t = r.table(root, "", "normal")) {
        r.onlyKeys(*t, "normal", {"channels", "space", "encoding", "axes"});
        NormalMapping& n = map.normal.emplace();
        n.space = r.choice(*t, "normal", "space", {"world", "view"}, 0) == 0 ? NormalSpace::World
                                                                             : NormalSpace::View;
        constexpr std::array<NormalStorage, 3> kStorage{NormalStorage::Unit, NormalStorage::Unorm,
                                                        NormalStorage::Octahedral};
        n.storage = kStorage[r.choice(*t, "normal", "encoding", {"unit", "unorm", "octahedral"}, 0)];
        const std::size_t count = n.storage == NormalStorage::Octahedral ? 2 : 3;
        n.channels = r.texts(*t, "normal", "channels", count, count);
        n.axes = r.axes(*t, "normal", "axes");
    }
    if (const toml::table* t = r.table(root, "", "roughness")) {
        r.onlyKeys(*t, "roughness", {"channel", "convention"});
        RoughnessMapping& g = map.roughness.emplace();
        g.channel = r.text(*t, "roughness", "channel", true);
        g.perceptual = r.choice(*t, "roughness", "convention", {"perceptual", "alpha"}, 0) == 0;
    }
    if (const toml::table* t = r.table(root, "", "motion")) readMotion(r, *t, map.motion.emplace());
    if (const toml::table* t = r.table(root, "", "shadow")) {
        r.onlyKeys(*t, "shadow", {"channel"});
        map.shadow = r.text(*t, "shadow", "channel", true);
    }
    if (const toml::table* t = r.table(root, "", "reference")) {
        r.onlyKeys(*t, "reference", {"reflection", "shadow"});
        if (const toml::table* s = r.table(*t, "reference", "reflection")) {
            r.onlyKeys(*s, "reference.reflection", {"channels"});
            map.referenceReflection = r.texts(*s, "reference.reflection", "channels", 3, 3);
        }
        if (const toml::table* s = r.table(*t, "reference", "shadow")) {
            r.onlyKeys(*s, "reference.shadow", {"channel"});
            map.referenceShadow = r.text(*s, "reference.shadow", "channel", true);
        }
    }
    if (const toml::table* t = r.table(root, "", "material")) {
        r.onlyKeys(*t, "material", {"base_color", "metallic", "optional"});
        map.baseColor = r.texts(*t, "material", "base_color", 3, 3);
        map.metallic = r.text(*t, "material", "metallic", false);
        map.materialOptional = r.flag(*t, "material", "optional", false);
    }
    const toml::table* camera = r.table(root, "", "camera");
    if (!camera) r.fail(&root, "camera", "missing [camera] section (required)");
    readCamera(r, *camera, map.camera);
    if (map.depth && map.depth->kind != DepthKind::Device &&
        map.camera.depth == DepthConvention::ReversedInfinite && std::isinf(map.depth->backgroundFrom))
        r.fail(root.get("depth"), "depth.background_from",
               "required with reversed_infinite depth (there is no far plane to mark the background)");
    if (map.motion && map.motion->background == BackgroundMotion::Camera && !map.depth)
        r.fail(root.get("motion"), "motion.background",
               "\"camera\" needs a [depth] section to find the background");
    checkEffects(r, root, map);
    checkReferences(r, root, map);
    return map;
}

std::string framesText(const ChannelMap& map) {
    std::string out = map.frames.size() == 1 ? "" : "[";
    for (std::size_t i = 0; i < map.frames.size(); ++i) out += (i ? ", \"" : "\"") + map.frames[i] + "\"";
    return out + (map.frames.size() == 1 ? "" : "]");
}

bool isExrFile(const std::filesystem::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".exr";
}

// "frame_2" before "frame_10": runs of digits compare as numbers.
bool naturalLess(const std::string& a, const std::string& b) {
    std::size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        const bool da = std::isdigit(static_cast<unsigned char>(a[i])) != 0;
        const bool db = std::isdigit(static_cast<unsigned char>(b[j])) != 0;
        if (da && db) {
            std::size_t ei = i, ej = j;
            while (ei < a.size() && std::isdigit(static_cast<unsigned char>(a[ei]))) ++ei;
            while (ej < b.size() && std::isdigit(static_cast<unsigned char>(b[ej]))) ++ej;
            std::string_view na(a.data() + i, ei - i), nb(b.data() + j, ej - j);
            while (na.size() > 1 && na[0] == '0') na.remove_prefix(1);
            while (nb.size() > 1 && nb[0] == '0') nb.remove_prefix(1);
            if (na.size() != nb.size()) return na.size() < nb.size();
            if (na != nb) return na < nb;
            i = ei;
            j = ej;
            continue;
        }
        if (a[i] != b[j]) return a[i] < b[j];
        ++i;
        ++j;
    }
    return a.size() - i < b.size() - j || (a.size() - i == b.size() - j && a < b);
}

std::filesystem::path resolveIn(const std::filesystem::path& folder, const std::string& name) {
    const std::filesystem::path p(name);
    return p.is_absolute() ? p : folder / p;
}

// One frame rather than a folder of frames: a file, or for folder frames a folder without
// sub-folders.
bool isOneFrame(const std::filesystem::path& p, const ChannelMap& map) {
    std::error_code ec;
    if (!map.framesAreFolders || !std::filesystem::is_directory(p, ec))
        return !std::filesystem::is_directory(p, ec);
    for (const auto& entry : std::filesystem::directory_iterator(p, ec))
        if (entry.is_directory(ec)) return false;
    return true;
}
} // namespace

bool matchesFramePattern(std::string_view name, std::string_view pattern) {
    // Iterative glob: on a mismatch, let the last `*` take one more character.
    std::size_t n = 0, p = 0, starP = std::string_view::npos, starN = 0;
    while (n < name.size()) {
        const bool one = p < pattern.size() &&
                         (pattern[p] == '?' || pattern[p] == name[n] ||
                          (pattern[p] == '#' && std::isdigit(static_cast<unsigned char>(name[n])) != 0));
        if (one) {
            ++n;
            ++p;
        } else if (p < pattern.size() && pattern[p] == '*') {
            starP = p++;
            starN = n;
        } else if (starP != std::string_view::npos) {
            p = starP + 1;
            n = ++starN;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

ChannelRef splitChannelRef(const std::string& ref) {
    std::string lower = ref;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const std::size_t at = lower.find(".exr:");
    if (at == 0 || at == std::string::npos || at + 5 == ref.size()) return {{}, ref};
    return {ref.substr(0, at + 4), ref.substr(at + 5)};
}

ChannelMap loadChannelMap(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) fail(path, "channel map file does not exist");
    toml::table root;
    try {
        root = toml::parse_file(path);
    } catch (const toml::parse_error& error) {
        throw CaptureError(path + ":" + std::to_string(error.source().begin.line),
                           "syntax: " + std::string(error.description()));
    }
    return parseMap(root, path);
}

std::vector<std::string> mappedSequenceFiles(const std::string& dirOrFile, const ChannelMap& map,
                                             std::vector<std::string>* ignored) {
    const std::filesystem::path p(dirOrFile);
    std::error_code ec;
    if (!std::filesystem::exists(p, ec)) fail(p, "does not exist");
    if (isOneFrame(p, map)) {
        if (map.framesAreFolders && !std::filesystem::is_directory(p, ec))
            fail(p, "the map " + map.path + " reads one folder of textures per frame, not a file");
        return {dirOrFile};
    }
    const std::filesystem::path folder(mappedCaptureFolder(dirOrFile, map));
    std::filesystem::path environment;
    if (!map.environment.file.empty()) environment = resolveIn(folder, map.environment.file);
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(p, ec)) {
        const bool frame = map.framesAreFolders ? entry.is_directory(ec)
                                                : entry.is_regular_file(ec) && isExrFile(entry.path());
        if (!frame) continue;
        std::error_code same; // an optional environment may not be there
        if (!environment.empty() && std::filesystem::equivalent(entry.path(), environment, same)) continue;
        const std::string name = entry.path().filename().string();
        const bool listed = map.frames.empty() ||
                            std::any_of(map.frames.begin(), map.frames.end(),
                                        [&](const std::string& f) { return matchesFramePattern(name, f); });
        if (listed)
            names.push_back(name);
        else if (ignored)
            ignored->push_back(name);
    }
    if (ec) fail(p, "cannot list the folder: " + ec.message());
    if (names.empty() && !map.frames.empty())
        fail(p, "holds no frames that match frames = " + framesText(map) + " in " + map.path);
    if (names.empty()) fail(p, map.framesAreFolders ? "holds no frame folders" : "holds no .exr files");
    std::sort(names.begin(), names.end(), naturalLess);
    if (ignored) std::sort(ignored->begin(), ignored->end(), naturalLess);
    std::vector<std::string> out;
    for (const std::string& name : names) out.push_back((p / name).string());
    return out;
}

std::string mappedCaptureFolder(const std::string& dirOrFile, const ChannelMap& map) {
    const std::filesystem::path p(dirOrFile);
    if (!isOneFrame(p, map)) return dirOrFile;
    return p.has_parent_path() ? p.parent_path().string() : std::string(".");
}

std::filesystem::path mappedEnvironmentFile(const ChannelMap& map, const std::string& dirOrFile) {
    if (map.environment.file.empty()) return {};
    return resolveIn(mappedCaptureFolder(dirOrFile, map), map.environment.file);
}

} // namespace glint::capture
