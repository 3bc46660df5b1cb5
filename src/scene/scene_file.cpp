#include "scene/scene_file.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/text_file.hpp"

namespace tp::scene {
namespace {

using nlohmann::json;

// Reads the fields of one JSON object, remembering which keys were consumed
// so that finish() can reject the rest by name.
class ObjectReader {
 public:
  ObjectReader(const json& object, std::string path, const std::string& origin)
      : object_(object), path_(std::move(path)), origin_(origin) {
    if (!object_.is_object()) fail(path_.empty() ? "the top level" : path_, "expected an object");
  }

  void number(const char* key, float& out) {
    if (const json* v = take(key)) {
      if (!v->is_number()) fail(name(key), "expected a number, got " + std::string(v->type_name()));
      out = v->get<float>();
    }
  }

  void count(const char* key, unsigned& out) {
    if (const json* v = take(key)) {
      if (!v->is_number_unsigned()) fail(name(key), "expected a non-negative integer, got " + v->dump());
      uint64_t value = v->get<uint64_t>();
      if (value > 1u << 30) fail(name(key), "is absurdly large (" + v->dump() + ")");
      out = unsigned(value);
    }
  }

  void vec3(const char* key, glm::vec3& out) {
    if (const json* v = take(key)) {
      if (!v->is_array() || v->size() != 3) fail(name(key), "expected an array of 3 numbers");
      for (int i = 0; i < 3; ++i) {
        if (!(*v)[i].is_number()) fail(name(key), "expected an array of 3 numbers");
        out[i] = (*v)[i].get<float>();
      }
    }
  }

  void flag(const char* key, bool& out) {
    if (const json* v = take(key)) {
      if (!v->is_boolean()) fail(name(key), "expected true or false, got " + std::string(v->type_name()));
      out = v->get<bool>();
    }
  }

  void text(const char* key, std::string& out) {
    if (const json* v = take(key)) {
      if (!v->is_string()) fail(name(key), "expected a string, got " + std::string(v->type_name()));
      out = v->get<std::string>();
    }
  }

  // An array of objects, each read into a T by readFields(reader, element).
  template <typename T, typename F>
  void objects(const char* key, std::vector<T>& out, F&& readFields) {
    if (const json* v = take(key)) {
      if (!v->is_array()) fail(name(key), "expected an array of objects");
      out.clear();
      for (size_t i = 0; i < v->size(); ++i) {
        ObjectReader child((*v)[i], name(key) + "[" + std::to_string(i) + "]", origin_);
        T element{};
        readFields(child, element);
        child.finish();
        out.push_back(element);
      }
    }
  }

  template <typename F>
  void object(const char* key, F&& readFields) {
    if (const json* v = take(key)) {
      ObjectReader child(*v, name(key), origin_);
      readFields(child);
      child.finish();
    }
  }

  // An AO preset name: replaces every AO setting with the preset's.
  void preset(const char* key, Ao& ao) {
    std::string presetName;
    text(key, presetName);
    if (presetName.empty()) return;
    try {
      ao = aoPreset(presetName);
    } catch (const std::invalid_argument& e) {
      fail(name(key), e.what());
    }
  }

  void finish() const {
    for (const auto& [key, value] : object_.items()) {
      if (!seen_.count(key)) fail(name(key.c_str()), "is not a known key");
    }
  }

 private:
  const json* take(const char* key) {
    seen_.insert(key);
    auto it = object_.find(key);
    return it == object_.end() ? nullptr : &*it;
  }
  std::string name(const char* key) const { return path_.empty() ? key : path_ + "." + key; }
  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw std::runtime_error(origin_ + ": " + where + ": " + what);
  }

  const json& object_;
  std::string path_;
  const std::string& origin_;
  std::set<std::string> seen_;
};

// The shortest decimal that reads back as the same float, as a JSON number:
// a saved scene reloads to the same bits and still reads like the one typed.
json exactNumber(float value) {
  char text[32];
  for (int digits = 6; digits <= 9; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, double(value));
    if (std::strtof(text, nullptr) == value) break;
  }
  return std::strtod(text, nullptr);
}

// Writes every field, with the same calls as ObjectReader reads them.
class ObjectWriter {
 public:
  void number(const char* key, float& value) { object_[key] = exactNumber(value); }
  void count(const char* key, unsigned& value) { object_[key] = value; }
  void vec3(const char* key, glm::vec3& value) {
    object_[key] = json::array({exactNumber(value.x), exactNumber(value.y), exactNumber(value.z)});
  }
  void flag(const char* key, bool& value) { object_[key] = value; }
  void text(const char* key, std::string& value) { object_[key] = value; }
  void preset(const char*, Ao&) {}  // the settings themselves are written, each one

  template <typename T, typename F>
  void objects(const char* key, std::vector<T>& values, F&& writeFields) {
    json array = json::array();
    for (T& element : values) {
      ObjectWriter child;
      writeFields(child, element);
      array.push_back(std::move(child.object_));
    }
    object_[key] = std::move(array);
  }

  template <typename F>
  void object(const char* key, F&& writeFields) {
    ObjectWriter child;
    writeFields(child);
    object_[key] = std::move(child.object_);
  }

  void finish() const {}
  const json& result() const { return object_; }

 private:
  json object_ = json::object();
};

// Every key of a scene file, once, for the reader and the writer alike: V
// is ObjectReader (fills `s` from JSON) or ObjectWriter (turns `s` into JSON).
template <typename V>
void visitScene(V& v, Scene& s) {
  v.object("camera", [&](auto& r) {
    r.vec3("position", s.camera.position);
    r.vec3("target", s.camera.target);
    r.vec3("up", s.camera.up);
    r.number("fov", s.camera.fovYDegrees);
    r.number("near", s.camera.nearPlane);
    r.number("far", s.camera.farPlane);
  });
  v.object("sky", [&](auto& r) {
    r.number("sun_elevation", s.sky.sunElevationDegrees);
    r.number("sun_azimuth", s.sky.sunAzimuthDegrees);
    r.number("sun_angular_radius", s.sky.sunAngularRadiusDegrees);
    r.vec3("sun_radiance", s.sky.sunRadiance);
    r.vec3("zenith", s.sky.zenith);
    r.vec3("horizon", s.sky.horizon);
    r.vec3("ground", s.sky.ground);
    r.vec3("glow", s.sky.glow);
    r.number("zenith_exponent", s.sky.zenithExponent);
    r.number("glow_exponent", s.sky.glowExponent);
    r.number("horizon_blend", s.sky.horizonBlend);
    r.count("texture_width", s.sky.textureWidth);
    r.text("image", s.sky.image);
  });
  v.object("ground", [&](auto& r) {
    r.number("half_extent", s.ground.halfExtent);
    r.number("height", s.ground.height);
    r.number("checker_size", s.ground.checkerSize);
    r.vec3("albedo_a", s.ground.albedoA);
    r.vec3("albedo_b", s.ground.albedoB);
  });
  v.object("water", [&](auto& r) {
    r.flag("enabled", s.water.enabled);
    r.count("grid", s.water.grid);
    r.number("extent", s.water.extent);
    r.number("level", s.water.level);
    r.number("wave_speed", s.water.waveSpeed);
    r.number("damping", s.water.damping);
    r.text("boundary", s.water.boundary);
    r.number("max_slope", s.water.maxSlope);
    r.number("frame_time", s.water.frameTime);
    r.number("ior", s.water.ior);
    r.vec3("absorption", s.water.absorption);
    r.objects("drops", s.water.drops, [](auto& d, scene::Drop& drop) {
      d.number("x", drop.x);
      d.number("z", drop.z);
      d.number("radius", drop.radius);
      d.number("amplitude", drop.amplitude);
      d.count("frame", drop.frame);
    });
  });
  v.object("pool", [&](auto& r) {
    r.number("depth", s.pool.depth);
    r.vec3("wall_albedo", s.pool.wallAlbedo);
    r.number("tile_size", s.pool.tileSize);
    r.vec3("tile_albedo_a", s.pool.tileAlbedoA);
    r.vec3("tile_albedo_b", s.pool.tileAlbedoB);
  });
  v.object("terrain", [&](auto& r) {
    r.number("amplitude", s.terrain.amplitude);
    r.number("frequency", s.terrain.frequency);
    r.count("octaves", s.terrain.octaves);
    r.number("persistence", s.terrain.persistence);
    r.count("seed", s.terrain.seed);
  });
  v.objects("spheres", s.spheres, [](auto& r, scene::Sphere& sphere) {
    r.vec3("center", sphere.center);
    r.number("radius", sphere.radius);
    r.vec3("albedo", sphere.albedo);
    r.objects("path", sphere.path, [](auto& k, scene::Keyframe& key) {
      k.number("time", key.time);
      k.vec3("center", key.center);
    });
  });
  v.objects("boxes", s.boxes, [](auto& r, scene::Box& box) {
    r.vec3("center", box.center);
    r.vec3("size", box.size);
    r.number("yaw", box.yawDegrees);
    r.vec3("albedo", box.albedo);
  });
  v.object("ao", [&](auto& r) {
    r.preset("preset", s.ao);  // first: the keys beside it override their own values alone
    r.flag("enabled", s.ao.enabled);
    r.text("pattern", s.ao.pattern);
    r.count("kernel_size", s.ao.kernelSize);
    r.number("radius", s.ao.radius);
    r.number("bias", s.ao.bias);
    r.count("noise_size", s.ao.noiseSize);
    r.text("depth_lookup", s.ao.depthLookup);
    r.text("blur", s.ao.blur);
    r.count("blur_taps", s.ao.blurTaps);
    r.number("blur_depth_tolerance", s.ao.blurDepthTolerance);
    r.text("resolution", s.ao.resolution);
  });
  v.object("render", [&](auto& r) {
    r.number("exposure", s.render.exposure);
    r.text("refraction", s.render.refraction);
    r.flag("caustics", s.render.caustics);
  });
}

}  // namespace

Scene parseScene(const std::string& text, const std::string& origin) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::exception& e) {  // parse_error, and out_of_range for 1e999
    throw std::runtime_error(origin + ": not valid JSON (" + e.what() + ")");
  }
  Scene s = defaultScene();
  ObjectReader top(root, "", origin);
  visitScene(top, s);
  top.finish();
  if (!s.sky.image.empty() && std::filesystem::path(s.sky.image).is_relative()) {
    s.sky.image = (std::filesystem::path(origin).parent_path() / s.sky.image).string();
  }
  try {
    validateScene(s);
  } catch (const std::exception& e) {
    throw std::runtime_error(origin + ": " + e.what());
  }
  return s;
}

std::string sceneToJson(const Scene& scene) {
  Scene copy = scene;
  ObjectWriter top;
  visitScene(top, copy);
  return top.result().dump(2) + "\n";
}

void saveSceneFile(const std::string& path, const Scene& scene) {
  io::requireExtension(path, ".json");
  io::AtomicFile file(path);
  {
    std::ofstream out(file.tempPath(), std::ios::binary);
    out << sceneToJson(scene);
    out.close();
    if (!out) throw std::runtime_error("cannot write scene file " + path);
  }
  file.commit();
}

Scene loadSceneFile(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw std::runtime_error("cannot read scene file " + path + ": not a file");
  const std::optional<std::string> text = io::readTextFile(path);
  if (!text) throw std::runtime_error("cannot read scene file " + path);
  return parseScene(*text, path);
}

}  // namespace tp::scene
