#include "scene/scene_file.hpp"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

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
  top.object("camera", [&](ObjectReader& r) {
    r.vec3("position", s.camera.position);
    r.vec3("target", s.camera.target);
    r.vec3("up", s.camera.up);
    r.number("fov", s.camera.fovYDegrees);
    r.number("near", s.camera.nearPlane);
    r.number("far", s.camera.farPlane);
  });
  top.object("sky", [&](ObjectReader& r) {
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
  top.object("ground", [&](ObjectReader& r) {
    r.number("half_extent", s.ground.halfExtent);
    r.number("height", s.ground.height);
    r.number("checker_size", s.ground.checkerSize);
    r.vec3("albedo_a", s.ground.albedoA);
    r.vec3("albedo_b", s.ground.albedoB);
  });
  top.object("water", [&](ObjectReader& r) {
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
    r.objects("drops", s.water.drops, [](ObjectReader& d, scene::Drop& drop) {
      d.number("x", drop.x);
      d.number("z", drop.z);
      d.number("radius", drop.radius);
      d.number("amplitude", drop.amplitude);
    });
  });
  top.object("pool", [&](ObjectReader& r) {
    r.number("depth", s.pool.depth);
    r.vec3("wall_albedo", s.pool.wallAlbedo);
    r.number("tile_size", s.pool.tileSize);
    r.vec3("tile_albedo_a", s.pool.tileAlbedoA);
    r.vec3("tile_albedo_b", s.pool.tileAlbedoB);
  });
  top.object("terrain", [&](ObjectReader& r) {
    r.number("amplitude", s.terrain.amplitude);
    r.number("frequency", s.terrain.frequency);
    r.count("octaves", s.terrain.octaves);
    r.number("persistence", s.terrain.persistence);
    r.count("seed", s.terrain.seed);
  });
  top.objects("spheres", s.spheres, [](ObjectReader& r, scene::Sphere& sphere) {
    r.vec3("center", sphere.center);
    r.number("radius", sphere.radius);
    r.vec3("albedo", sphere.albedo);
    r.objects("path", sphere.path, [](ObjectReader& k, scene::Keyframe& key) {
      k.number("time", key.time);
      k.vec3("center", key.center);
    });
  });
  top.objects("boxes", s.boxes, [](ObjectReader& r, scene::Box& box) {
    r.vec3("center", box.center);
    r.vec3("size", box.size);
    r.number("yaw", box.yawDegrees);
    r.vec3("albedo", box.albedo);
  });
  top.object("ao", [&](ObjectReader& r) {
    // A preset first, then any key given beside it overrides that key alone.
    std::string preset;
    r.text("preset", preset);
    if (!preset.empty()) {
      try {
        s.ao = aoPreset(preset);
      } catch (const std::invalid_argument& e) {
        throw std::runtime_error(origin + ": ao.preset: " + e.what());
      }
    }
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
  top.object("render", [&](ObjectReader& r) {
    r.number("exposure", s.render.exposure);
    r.text("refraction", s.render.refraction);
    r.flag("caustics", s.render.caustics);
  });
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

Scene loadSceneFile(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw std::runtime_error("cannot read scene file " + path + ": not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read scene file " + path);
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw std::runtime_error("cannot read scene file " + path);
  return parseScene(text.str(), path);
}

}  // namespace tp::scene
