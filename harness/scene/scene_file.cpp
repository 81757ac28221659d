#include "scene/scene_file.h"

#include "scene/scene_geometry.h"

#include <toml++/toml.h>

#include <stdexcept>

#include <cmath>
#include <fstream>
#include <initializer_list>
#include <map>
#include <sstream>

namespace glint::scene {
namespace {

// Reads one TOML table with the path of keys that led to it, so that every message can name
// the file, the line and the full key ("objects[2].material").
struct Reader {
    const std::filesystem::path& file;

    [[noreturn]] void fail(const toml::node* node, const std::string& key, const std::string& problem) const {
        std::string message = file.string();
        if (node && node->source().begin.line > 0) {
            message.append(":");
            message.append(std::to_string(node->source().begin.line));
        }
        message.append(": ");
        message.append(key);
        message.append(": ");
        message.append(problem);
        throw SceneError(message);
    }

    // Unknown keys are errors: a misspelt key silently ignored is a scene that lies.
    void onlyKeys(const toml::table& table, const std::string& prefix,
                  std::initializer_list<std::string_view> allowed) const {
        for (const auto& [key, node] : table) {
            bool known = false;
            for (std::string_view name : allowed) known = known || key.str() == name;
            if (!known) fail(&node, join(prefix, std::string(key.str())), "unknown key");
        }
    }

    static std::string join(const std::string& prefix, const std::string& key) {
        if (prefix.empty()) return key;
        std::string out = prefix;
        out.append(".");
        out.append(key);
        return out;
    }

    double number(const toml::table& t, const std::string& prefix, const char* key, double fallback,
                  double lo = -1e30, double hi = 1e30) const {
        const toml::node* node = t.get(key);
        if (!node) return fallback;
        std::optional<double> value = node->value<double>();
        if (!value || !std::isfinite(*value)) fail(node, join(prefix, key), "expected a finite number");
        if (*value < lo || *value > hi) {
            std::ostringstream s;
            s << "value " << *value << " is outside [" << lo << ", " << hi << "]";
            fail(node, join(prefix, key), s.str());
        }
        return *value;
    }

    float real(const toml::table& t, const std::string& prefix, const char* key, float fallback,
               double lo = -1e30, double hi = 1e30) const {
        return static_cast<float>(number(t, prefix, key, static_cast<double>(fallback), lo, hi));
    }

    std::uint32_t count(const toml::table& t, const std::string& prefix, const char* key,
                        std::uint32_t fallback, std::int64_t lo, std::int64_t hi) const {
        const toml::node* node = t.get(key);
        if (!node) return fallback;
        std::optional<std::int64_t> value = node->value_exact<std::int64_t>();
        if (!value) fail(node, join(prefix, key), "expected an integer");
        if (*value < lo || *value > hi)
            fail(node, join(prefix, key),
                 "value " + std::to_string(*value) + " is outside [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "]");
        return static_cast<std::uint32_t>(*value);
    }

    bool flag(const toml::table& t, const std::string& prefix, const char* key, bool fallback) const {
        const toml::node* node = t.get(key);
        if (!node) return fallback;
        std::optional<bool> value = node->value_exact<bool>();
        if (!value) fail(node, join(prefix, key), "expected true or false");
        return *value;
    }

    std::string text(const toml::table& t, const std::string& prefix, const char* key,
                     const std::string& fallback) const {
        const toml::node* node = t.get(key);
        if (!node) return fallback;
        std::optional<std::string> value = node->value_exact<std::string>();
        if (!value) fail(node, join(prefix, key), "expected a string");
        return *value;
    }

    std::vector<double> numbers(const toml::node* node, const std::string& key, std::size_t n) const {
        const toml::array* array = node->as_array();
        if (!array || array->size() != n)
            fail(node, key, "expected an array of " + std::to_string(n) + " numbers");
        std::vector<double> out;
        for (const toml::node& element : *array) {
            std::optional<double> value = element.value<double>();
            if (!value || !std::isfinite(*value)) fail(&element, key, "expected an array of finite numbers");
            out.push_back(*value);
        }
        return out;
    }

    Vec3 vec3(const toml::table& t, const std::string& prefix, const char* key, Vec3 fallback) const {
        const toml::node* node = t.get(key);
        if (!node) return fallback;
        const std::vector<double> v = numbers(node, join(prefix, key), 3);
        return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
    }

    std::optional<capture::Mat4> matrix(const toml::table& t, const std::string& prefix,
                                        const char* key) const {
        const toml::node* node = t.get(key);
        if (!node) return std::nullopt;
        const std::vector<double> v = numbers(node, join(prefix, key), 16);
        capture::Mat4 m;
        for (std::size_t i = 0; i < 16; ++i) m.m[i] = v[i];
        if (!capture::inverse(m)) fail(node, join(prefix, key), "matrix is singular");
        return m;
    }

    const toml::table* table(const toml::table& t, const std::string& prefix, const char* key) const {
        const toml::node* node = t.get(key);
        if (!node) return nullptr;
        if (!node->is_table()) fail(node, join(prefix, key), "expected a table");
        return node->as_table();
    }

    // An array of tables ([[key]]); empty when absent.
    std::vector<const toml::table*> tables(const toml::table& t, const std::string& prefix,
                                           const char* key) const {
        std::vector<const toml::table*> out;
        const toml::node* node = t.get(key);
        if (!node) return out;
        const toml::array* array = node->as_array();
        if (!array)
            fail(node, join(prefix, key), "expected an array of tables ([[" + join(prefix, key) + "]])");
        for (const toml::node& element : *array) {
            if (!element.is_table()) fail(&element, join(prefix, key), "expected an array of tables");
            out.push_back(element.as_table());
        }
        return out;
    }

    std::filesystem::path path(const toml::table& t, const std::string& prefix, const char* key) const {
        std::filesystem::path p = text(t, prefix, key, "");
        if (p.empty()) fail(t.get(key) ? t.get(key) : &t, join(prefix, key), "a file path is required");
        if (p.is_relative()) p = file.parent_path() / p;
        if (!std::filesystem::is_regular_file(p))
            fail(t.get(key), join(prefix, key), "file '" + p.string() + "' does not exist");
        return p;
    }
};

std::string indexed(const char* key, std::size_t i) {
    std::string s = key;
    s.append("[");
    s.append(std::to_string(i));
    s.append("]");
    return s;
}

std::string vectorText(const double (&v)[3]) {
    std::ostringstream s;
    s << "[" << v[0] << ", " << v[1] << ", " << v[2] << "]";
    return s.str();
}

// A look-at camera needs a view direction that is neither zero nor parallel to camera.up on
// every frame it renders, and on the frame before the first (the previous camera of frame 0);
// otherwise its right vector, cross(direction, up), is zero and the view matrix is not finite.
// Each key is checked too: frames past the last one (--frame-count) show it.
void checkLookAt(const Reader& r, const toml::table& t, const Scene& scene) {
    const CameraDesc& c = scene.camera;
    const double up[3] = {static_cast<double>(c.up[0]), static_cast<double>(c.up[1]),
                          static_cast<double>(c.up[2])};
    const double upLength = std::sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
    const toml::node* upNode = t.get("up") ? t.get("up") : &t;
    if (!(upLength > 0.0)) r.fail(upNode, "camera.up", "must not be zero");
    const auto check = [&](const Vec3& position, const Vec3& target, const std::string& when) {
        const double eye[3] = {static_cast<double>(position[0]), static_cast<double>(position[1]),
                               static_cast<double>(position[2])};
        const double f[3] = {static_cast<double>(target[0]) - eye[0], static_cast<double>(target[1]) - eye[1],
                             static_cast<double>(target[2]) - eye[2]};
        const double length = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        if (!(length > 0.0))
            r.fail(t.get("target") ? t.get("target") : &t, "camera.target",
                   "equals camera.position " + vectorText(eye) + " " + when + ": the camera looks nowhere");
        const double x[3] = {f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2],
                             f[0] * up[1] - f[1] * up[0]};
        const double sine = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) / (length * upLength);
        if (sine < 1e-6) {
            const double direction[3] = {f[0] / length, f[1] / length, f[2] / length};
            r.fail(upNode, "camera.up",
                   std::string(t.get("up") ? "" : "the default ") + vectorText(up) +
                       " is parallel to the view direction " + vectorText(direction) + " " + when +
                       "; give camera.up a direction across the view (for a camera looking straight up or "
                       "down, e.g. [0, 0, -1])");
        }
    };
    for (std::int64_t frame = 0; frame < static_cast<std::int64_t>(scene.frameCount); ++frame) {
        const auto [position, target] = cameraEyeTarget(c, static_cast<double>(frame));
        check(position, target, "on frame " + std::to_string(frame));
    }
    const auto [position, target] = cameraEyeTarget(c, -1.0);
    check(position, target, "on frame -1 (the previous camera of frame 0)");
    if (c.keys.size() > 1)
        for (std::size_t i = 0; i < c.keys.size(); ++i)
            check(c.keys[i].position, c.keys[i].target, "at camera.keyframes[" + std::to_string(i) + "]");
}

void readCamera(const Reader& r, const toml::table& t, Scene& scene) {
    const std::string p = "camera";
    r.onlyKeys(t, p,
               {"position", "target", "up", "fov_y", "near", "far", "depth", "ndc_y_down", "view",
                "projection", "keyframes"});
    CameraDesc& c = scene.camera;
    CameraKey key;
    key.position = r.vec3(t, p, "position", key.position);
    key.target = r.vec3(t, p, "target", key.target);
    c.up = r.vec3(t, p, "up", c.up);
    c.fovYDegrees = r.number(t, p, "fov_y", c.fovYDegrees, 1.0, 179.0);
    c.nearZ = r.number(t, p, "near", c.nearZ, 1e-6, 1e9);
    c.farZ = r.number(t, p, "far", c.farZ, 1e-6, 1e12);
    const std::string depth = r.text(t, p, "depth", "standard");
    if (depth == "standard")
        c.depth = capture::DepthConvention::Standard;
    else if (depth == "reversed")
        c.depth = capture::DepthConvention::Reversed;
    else if (depth == "reversed_infinite")
        c.depth = capture::DepthConvention::ReversedInfinite;
    else
        r.fail(t.get("depth"), "camera.depth",
               "expected \"standard\", \"reversed\" or \"reversed_infinite\"");
    if (c.depth != capture::DepthConvention::ReversedInfinite && c.farZ <= c.nearZ)
        r.fail(t.get("far"), "camera.far", "must be greater than camera.near");
    c.ndcYDown = r.flag(t, p, "ndc_y_down", false);
    c.view = r.matrix(t, p, "view");
    c.projection = r.matrix(t, p, "projection");
    c.keys = {key};
    const auto keys = r.tables(t, p, "keyframes");
    if (!keys.empty() && c.view)
        r.fail(t.get("keyframes"), "camera.keyframes", "cannot animate a camera given by a view matrix");
    if (!keys.empty()) c.keys.clear();
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const std::string kp = "camera." + indexed("keyframes", i);
        r.onlyKeys(*keys[i], kp, {"frame", "position", "target"});
        CameraKey k = key;
        k.frame = r.real(*keys[i], kp, "frame", 0.0f, -1e6, 1e6);
        if (!c.keys.empty() && k.frame <= c.keys.back().frame)
            r.fail(keys[i], kp + ".frame", "keyframes must be in increasing frame order");
        k.position = r.vec3(*keys[i], kp, "position", c.keys.empty() ? key.position : c.keys.back().position);
        k.target = r.vec3(*keys[i], kp, "target", c.keys.empty() ? key.target : c.keys.back().target);
        c.keys.push_back(k);
    }
    if (!c.view) checkLookAt(r, t, scene);
}

void readEnvironment(const Reader& r, const toml::table& t, Scene& scene) {
    const std::string p = "environment";
    r.onlyKeys(t, p, {"type", "file", "intensity", "zenith", "horizon", "ground", "sun_disc", "resolution"});
    EnvironmentDesc& e = scene.environment;
    const std::string type = r.text(t, p, "type", "sky");
    if (type == "sky")
        e.kind = EnvironmentKind::Sky;
    else if (type == "map")
        e.kind = EnvironmentKind::Map;
    else
        r.fail(t.get("type"), "environment.type", "expected \"sky\" or \"map\"");
    if (e.kind == EnvironmentKind::Map) e.file = r.path(t, p, "file");
    e.intensity = r.real(t, p, "intensity", e.intensity, 0.0, 1e6);
    e.zenith = r.vec3(t, p, "zenith", e.zenith);
    e.horizon = r.vec3(t, p, "horizon", e.horizon);
    e.ground = r.vec3(t, p, "ground", e.ground);
    e.sunDisc = r.flag(t, p, "sun_disc", e.sunDisc);
    if (const toml::node* node = t.get("resolution")) {
        const std::vector<double> v = r.numbers(node, "environment.resolution", 2);
        if (v[0] < 4 || v[1] < 2 || v[0] > 8192 || v[1] > 4096 || v[0] != std::floor(v[0]) ||
            v[1] != std::floor(v[1]))
            r.fail(node, "environment.resolution",
                   "expected [width, height] integers in [4, 8192] x [2, 4096]");
        e.width = static_cast<std::uint32_t>(v[0]);
        e.height = static_cast<std::uint32_t>(v[1]);
    }
}

// A "direction" key: non-zero, returned normalised.
Vec3 direction(const Reader& r, const toml::table& t, const std::string& p, const Vec3& fallback) {
    Vec3 d = r.vec3(t, p, "direction", fallback);
    const float len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(len > 1e-6f)) r.fail(t.get("direction"), p + ".direction", "must not be zero");
    for (float& c : d) c /= len;
    return d;
}

void readLights(const Reader& r, const toml::table& root, Scene& scene) {
    const auto lights = r.tables(root, "", "lights");
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const toml::table& t = *lights[i];
        const std::string p = indexed("lights", i);
        r.onlyKeys(
            t, p,
            {"type", "direction", "position", "color", "intensity", "angular_radius", "radius", "keyframes"});
        LightDesc l;
        const std::string type = r.text(t, p, "type", "directional");
        if (type == "directional")
            l.kind = LightKind::Directional;
        else if (type == "sphere")
            l.kind = LightKind::Sphere;
        else
            r.fail(t.get("type"), p + ".type", "expected \"directional\" or \"sphere\"");
        l.direction = direction(r, t, p, l.direction);
        l.position = r.vec3(t, p, "position", l.position);
        l.color = r.vec3(t, p, "color", l.color);
        l.intensity = r.real(t, p, "intensity", l.intensity, 0.0, 1e9);
        l.angularRadiusDegrees = r.real(t, p, "angular_radius", l.angularRadiusDegrees, 0.0, 45.0);
        l.radius = r.real(t, p, "radius", l.radius, 0.0, 1e6);
        const auto keys = r.tables(t, p, "keyframes");
        for (std::size_t k = 0; k < keys.size(); ++k) {
            const std::string kp = p + "." + indexed("keyframes", k);
            r.onlyKeys(*keys[k], kp, {"frame", "direction", "position"});
            LightKey key;
            key.frame = r.real(*keys[k], kp, "frame", 0.0f, -1e6, 1e6);
            if (!l.keys.empty() && key.frame <= l.keys.back().frame)
                r.fail(keys[k], kp + ".frame", "keyframes must be in increasing frame order");
            // Missing values carry over from the previous key (the light's own on the first).
            const LightKey& previous =
                l.keys.empty() ? LightKey{0.0f, l.direction, l.position} : l.keys.back();
            key.direction = direction(r, *keys[k], kp, previous.direction);
            key.position = r.vec3(*keys[k], kp, "position", previous.position);
            if (!l.keys.empty()) {
                // Directions are interpolated linearly and renormalised, which is undefined
                // through the midpoint of opposite directions.
                const Vec3& a = l.keys.back().direction;
                const Vec3& b = key.direction;
                if (a[0] * b[0] + a[1] * b[1] + a[2] * b[2] < -0.99f)
                    r.fail(keys[k]->get("direction") ? keys[k]->get("direction") : keys[k], kp + ".direction",
                           "turns by nearly 180 degrees from the previous key; add a key in between");
            }
            l.keys.push_back(key);
        }
        scene.lights.push_back(l);
    }
}

std::map<std::string, std::uint32_t> readMaterials(const Reader& r, const toml::table& root, Scene& scene) {
    std::map<std::string, std::uint32_t> byName;
    const toml::table* materials = r.table(root, "", "materials");
    if (!materials) return byName;
    for (const auto& [name, node] : *materials) {
        const std::string p = "materials." + std::string(name.str());
        if (!node.is_table())
            r.fail(&node, p, "expected a table ([materials." + std::string(name.str()) + "])");
        const toml::table& t = *node.as_table();
        r.onlyKeys(t, p, {"base_color", "metallic", "roughness", "emissive", "roughness_ramp"});
        MaterialDesc m;
        m.name = std::string(name.str());
        m.baseColor = r.vec3(t, p, "base_color", m.baseColor);
        m.metallic = r.real(t, p, "metallic", m.metallic, 0.0, 1.0);
        m.roughness = r.real(t, p, "roughness", m.roughness, 0.0, 1.0);
        m.emissive = r.vec3(t, p, "emissive", m.emissive);
        if (const toml::table* ramp = r.table(t, p, "roughness_ramp")) {
            const std::string rp = p + ".roughness_ramp";
            r.onlyKeys(*ramp, rp, {"start", "end", "from", "to"});
            m.ramp = true;
            m.rampStart = r.vec3(*ramp, rp, "start", {-1.0f, 0.0f, 0.0f});
            m.rampEnd = r.vec3(*ramp, rp, "end", {1.0f, 0.0f, 0.0f});
            m.roughness = r.real(*ramp, rp, "from", 0.0f, 0.0, 1.0);
            m.rampRoughnessEnd = r.real(*ramp, rp, "to", 1.0f, 0.0, 1.0);
            const Vec3& a = m.rampStart;
            const Vec3& b = m.rampEnd;
            if (a == b) r.fail(ramp, rp, "start and end must differ");
        }
        byName[m.name] = static_cast<std::uint32_t>(scene.materials.size());
        scene.materials.push_back(m);
    }
    return byName;
}

ObjectKey readObjectKey(const Reader& r, const toml::table& t, const std::string& p,
                        const ObjectKey& fallback) {
    ObjectKey k = fallback;
    k.position = r.vec3(t, p, "position", k.position);
    k.rotationDegrees = r.vec3(t, p, "rotation", k.rotationDegrees);
    k.scale = r.vec3(t, p, "scale", k.scale);
    return k;
}

void readObjects(const Reader& r, const toml::table& root, Scene& scene,
                 const std::map<std::string, std::uint32_t>& materials) {
    const auto objects = r.tables(root, "", "objects");
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const toml::table& t = *objects[i];
        const std::string p = indexed("objects", i);
        r.onlyKeys(t, p,
                   {"name", "type", "material", "size", "radius", "file", "fit_size", "position", "rotation",
                    "scale", "keyframes"});
        ObjectDesc o;
        o.name = r.text(t, p, "name", p);
        const std::string type = r.text(t, p, "type", "");
        if (type == "plane")
            o.shape = ShapeKind::Plane;
        else if (type == "box")
            o.shape = ShapeKind::Box;
        else if (type == "sphere")
            o.shape = ShapeKind::Sphere;
        else if (type == "mesh")
            o.shape = ShapeKind::Mesh;
        else
            r.fail(t.get("type") ? t.get("type") : &t, p + ".type",
                   "expected \"plane\", \"box\", \"sphere\" or \"mesh\"");
        const std::string material = r.text(t, p, "material", "");
        const auto found = materials.find(material);
        if (found == materials.end())
            r.fail(t.get("material") ? t.get("material") : &t, p + ".material",
                   "unknown material '" + material + "'");
        o.material = found->second;
        if (const toml::node* node = t.get("size")) {
            const std::vector<double> v = r.numbers(node, p + ".size", o.shape == ShapeKind::Plane ? 2 : 3);
            o.size = {static_cast<float>(v[0]), o.shape == ShapeKind::Plane ? 0.0f : static_cast<float>(v[1]),
                      static_cast<float>(v.back())};
        }
        o.radius = r.real(t, p, "radius", o.radius, 1e-6, 1e6);
        if (o.shape == ShapeKind::Mesh) o.file = r.path(t, p, "file");
        o.fitSize = r.real(t, p, "fit_size", 0.0f, 0.0, 1e6);
        const ObjectKey base = readObjectKey(r, t, p, ObjectKey{});
        o.keys = {base};
        const auto keys = r.tables(t, p, "keyframes");
        if (!keys.empty()) o.keys.clear();
        for (std::size_t k = 0; k < keys.size(); ++k) {
            const std::string kp = p + "." + indexed("keyframes", k);
            r.onlyKeys(*keys[k], kp, {"frame", "position", "rotation", "scale"});
            ObjectKey key = readObjectKey(r, *keys[k], kp, o.keys.empty() ? base : o.keys.back());
            key.frame = r.real(*keys[k], kp, "frame", 0.0f, -1e6, 1e6);
            if (!o.keys.empty() && key.frame <= o.keys.back().frame)
                r.fail(keys[k], kp + ".frame", "keyframes must be in increasing frame order");
            o.keys.push_back(key);
        }
        scene.objects.push_back(o);
    }
}

void readEffects(const Reader& r, const toml::table& root, Scene& scene) {
    const toml::node* node = root.get("effects");
    if (!node)
        r.fail(&root, "effects",
               "missing: declare what the capture is for, e.g. effects = [\"reflections\"]");
    const toml::array* array = node->as_array();
    if (!array || array->empty()) r.fail(node, "effects", "expected a non-empty array of strings");
    for (const toml::node& element : *array) {
        std::optional<std::string> name = element.value_exact<std::string>();
        Effect e{};
        if (name == "reflections")
            e = Effect::Reflections;
        else if (name == "shadows")
            e = Effect::Shadows;
        else if (name == "hybrid")
            e = Effect::Hybrid;
        else
            r.fail(&element, "effects",
                   "unknown effect '" + name.value_or("?") + "' (known: reflections, shadows, hybrid)");
        if (hasEffect(scene, e)) r.fail(&element, "effects", "effect '" + *name + "' is listed twice");
        scene.effects.push_back(e);
    }
}

} // namespace

bool hasEffect(const Scene& scene, Effect effect) {
    for (Effect e : scene.effects)
        if (e == effect) return true;
    return false;
}
bool needsReflections(const Scene& scene) {
    return hasEffect(scene, Effect::Reflections) || hasEffect(scene, Effect::Hybrid);
}
Effect effectNamed(std::string_view name) {
    if (name == "reflections") return Effect::Reflections;
    if (name == "shadows") return Effect::Shadows;
    if (name == "hybrid") return Effect::Hybrid;
    throw std::invalid_argument("no scene effect '" + std::string(name) + "' (reflections, shadows, hybrid)");
}

void requestReference(ReferenceDesc& reference, std::string_view layer) {
    if (layer == "reflection")
        reference.reflections = true;
    else if (layer == "shadow")
        reference.shadows = true;
    else
        throw std::invalid_argument("no scene renders the reference layer 'reference." + std::string(layer) +
                                    "'");
}

bool needsShadows(const Scene& scene) {
    return hasEffect(scene, Effect::Shadows);
}

Scene parseScene(const std::string& text, const std::filesystem::path& file) {
    toml::table root;
    try {
        root = toml::parse(text, file.string());
    } catch (const toml::parse_error& error) {
        std::string message = file.string();
        message.append(":");
        message.append(std::to_string(error.source().begin.line));
        message.append(": syntax: ");
        message.append(std::string(error.description()));
        throw SceneError(message);
    }
    const Reader r{file};
    r.onlyKeys(root, "",
               {"resolution", "frames", "frame_rate", "seed", "shadow_samples", "shadow_light", "effects",
                "camera", "environment", "lights", "materials", "objects", "reference"});
    Scene scene;
    scene.file = file;
    if (const toml::node* node = root.get("resolution")) {
        const std::vector<double> v = r.numbers(node, "resolution", 2);
        if (v[0] < 1 || v[1] < 1 || v[0] > 16384 || v[1] > 16384 || v[0] != std::floor(v[0]) ||
            v[1] != std::floor(v[1]))
            r.fail(node, "resolution", "expected [width, height] integers in 1 .. 16384");
        scene.width = static_cast<std::uint32_t>(v[0]);
        scene.height = static_cast<std::uint32_t>(v[1]);
    }
    scene.frameCount = r.count(root, "", "frames", 1, 1, 100000);
    scene.frameRate = r.number(root, "", "frame_rate", 30.0, 1e-3, 1e6);
    scene.seed = r.count(root, "", "seed", 1, 0, 0xFFFFFFFFll);
    scene.shadowSamples = r.count(root, "", "shadow_samples", 16, 1, 4096);
    readEffects(r, root, scene);
    if (const toml::table* t = r.table(root, "", "camera")) readCamera(r, *t, scene);
    if (const toml::table* t = r.table(root, "", "environment")) readEnvironment(r, *t, scene);
    readLights(r, root, scene);
    const auto materials = readMaterials(r, root, scene);
    readObjects(r, root, scene, materials);
    scene.shadowLight = r.count(root, "", "shadow_light", 0, 0, 1000000);
    if (needsShadows(scene) && scene.shadowLight >= scene.lights.size())
        r.fail(root.get("shadow_light") ? root.get("shadow_light") : &root, "shadow_light",
               "effect 'shadows' needs a light: " + std::to_string(scene.lights.size()) +
                   " light(s) declared");
    if (const toml::table* t = r.table(root, "", "reference")) {
        r.onlyKeys(*t, "reference",
                   {"reflections", "shadows", "spp", "environment_sampling", "accumulate", "noise_target",
                    "max_spp", "noise_target_alpha_below"});
        scene.reference.reflections = r.flag(*t, "reference", "reflections", false);
        scene.reference.shadows = r.flag(*t, "reference", "shadows", false);
        scene.reference.samplesPerPixel = r.count(*t, "reference", "spp", 64, 1, 1 << 20);
        scene.reference.environmentSampling =
            r.flag(*t, "reference", "environment_sampling", scene.reference.environmentSampling);
        scene.reference.accumulate = r.flag(*t, "reference", "accumulate", scene.reference.accumulate);
        scene.reference.noiseTarget = r.real(*t, "reference", "noise_target", 0.0f, 0.0, 1.0);
        scene.reference.maxSamplesPerPixel = r.count(*t, "reference", "max_spp", 0, 0, 1 << 20);
        scene.reference.noiseTargetAlphaBelow = r.real(*t, "reference", "noise_target_alpha_below",
                                                       scene.reference.noiseTargetAlphaBelow, 0.0, 1.0);
        if (scene.reference.reflections && !needsReflections(scene))
            r.fail(t->get("reflections"), "reference.reflections", "needs effect 'reflections' or 'hybrid'");
        if (scene.reference.shadows && !needsShadows(scene))
            r.fail(t->get("shadows"), "reference.shadows", "needs effect 'shadows'");
    }
    return scene;
}

Scene loadScene(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw SceneError(file.string() + ": cannot open the scene file");
    std::ostringstream text;
    text << in.rdbuf();
    return parseScene(text.str(), file);
}

} // namespace glint::scene
