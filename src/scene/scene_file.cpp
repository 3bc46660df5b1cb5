#include "scene/scene_file.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <vector>

#include "base/atomic_file.hpp"
#include "base/closest_word.hpp"
#include "base/text_file.hpp"
#include "scene/scene_keys.hpp"

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

  void color(const char* key, glm::vec3& out) { vec3(key, out); }

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

  // One of `allowed` (validateScene says which, naming the key, when not).
  void choice(const char* key, std::string& out, const std::vector<std::string>&) { text(key, out); }

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

  // Refuses a key no read asked for, naming the nearest one asked for, as
  // --set does (the keys asked for are this object's).
  void finish() const {
    for (const auto& [key, value] : object_.items()) {
      if (seen_.count(key)) continue;
      const auto guess = base::closestWord(key, std::vector<std::string>(seen_.begin(), seen_.end()));
      fail(name(key.c_str()), "is not a known key" + (guess ? "; did you mean " + name(guess->c_str()) + "?" : ""));
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
  void color(const char* key, glm::vec3& value) { vec3(key, value); }
  void flag(const char* key, bool& value) { object_[key] = value; }
  void text(const char* key, std::string& value) { object_[key] = value; }
  void choice(const char* key, std::string& value, const std::vector<std::string>&) { object_[key] = value; }
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

// Watches the parser's events for a key given twice in one object (JSON
// allows it and the parser keeps the last): where the element being read
// sits, one segment per open object or array, and the keys each open object
// has had. Paths are spelled only for the error, so a deep file costs little.
class DuplicateKeys {
 public:
  explicit DuplicateKeys(std::string origin) : origin_(std::move(origin)) {}

  bool operator()(int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
        open_.push_back({false, 0, {}});
        keys_.emplace_back();
        break;
      case json::parse_event_t::array_start:
        open_.push_back({true, 0, {}});
        break;
      case json::parse_event_t::key: {
        const std::string& key = parsed.get_ref<const std::string&>();
        open_.back().key = key;
        if (!keys_.back().insert(key).second) {
          throw std::runtime_error(origin_ + ": " + path() + ": the key appears twice in one object");
        }
        break;
      }
      case json::parse_event_t::object_end:
        keys_.pop_back();
        open_.pop_back();
        elementDone();
        break;
      case json::parse_event_t::array_end:
        open_.pop_back();
        elementDone();
        break;
      case json::parse_event_t::value:
        elementDone();
        break;
    }
    return true;
  }

 private:
  struct Segment {
    bool array;
    size_t index;     // arrays: the element being read
    std::string key;  // objects: the last key read
  };
  void elementDone() {
    if (!open_.empty() && open_.back().array) ++open_.back().index;
  }
  std::string path() const {
    std::string p;
    for (const Segment& s : open_) {
      if (s.array) {
        p += "[" + std::to_string(s.index) + "]";
      } else {
        p += (p.empty() ? "" : ".") + s.key;
      }
    }
    return p;
  }

  std::string origin_;
  std::vector<Segment> open_;
  std::vector<std::set<std::string>> keys_;
};

}  // namespace

Scene parseScene(const std::string& text, const std::string& origin) {
  json root;
  try {
    root = json::parse(text, DuplicateKeys(origin));
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

namespace {

// A list of objects (spheres, boxes, camera.path), as opposed to a vector of numbers.
bool isList(const json& value) { return value.is_array() && (value.empty() || value.front().is_object()); }

// Names what `key` may have meant: the nearest key beside it in the scene
// (water.grdi: water.grid), else the keys of the object it is under.
std::string unknownKeyMessage(const json& root, const std::string& key) {
  const json* parent = &root;
  std::string parentName, last = key;
  size_t start = 0;
  for (size_t dot = key.find('.'); dot != std::string::npos; dot = key.find('.', start)) {
    const std::string part = key.substr(start, dot - start);
    const json* child = nullptr;
    if (parent->is_object() && parent->contains(part)) child = &(*parent)[part];
    if (parent->is_array() && !part.empty() && part.find_first_not_of("0123456789") == std::string::npos &&
        std::stoul(part) < parent->size()) {
      child = &(*parent)[std::stoul(part)];
    }
    if (!child) break;
    parent = child;
    parentName = key.substr(0, dot + 1);
    start = dot + 1;
    last = key.substr(start);
  }
  std::string message = key + ": not a key of the scene";
  if (isList(*parent)) {
    const std::string list = parentName.substr(0, parentName.size() - 1), next = std::to_string(parent->size());
    std::string elements = " has no elements";
    if (parent->size() == 1) elements = " has 1 element (0)";
    if (parent->size() > 1) elements = " has " + next + " elements (0 to " + std::to_string(parent->size() - 1) + ")";
    return message + "; " + list + elements + "; to add one, set it whole: --set '" + list + "." + next + "={...}'";
  }
  if (!parent->is_object())
    return message + " (keys are a scene file's, joined by dots: water.wave_speed, spheres.0.radius)";
  std::vector<std::string> names;
  for (const auto& item : parent->items()) names.push_back(item.key());
  const std::string head = last.substr(0, last.find('.'));
  if (auto guess = base::closestWord(head, names)) {
    return message + "; did you mean " + parentName + *guess + last.substr(head.size()) + "?";
  }
  return message + (parentName.empty() ? "; its objects are " : "; " + parentName + " has ") + base::listWords(names);
}

// Whether `at` is one past the end of a list (spheres.1 where there is one
// sphere): setting it adds an element, its absent keys at their defaults.
bool appendsToList(const json& root, const json::json_pointer& at) {
  const json::json_pointer list = at.parent_pointer();
  if (!root.contains(list) || !isList(root[list])) return false;
  return at.back() == std::to_string(root[list].size());
}

}  // namespace

Scene withSetting(const Scene& scene, const std::string& key, const std::string& value) {
  json root = json::parse(sceneToJson(scene));
  std::string pointer = "/" + key;
  std::replace(pointer.begin(), pointer.end(), '.', '/');
  json setting;
  try {
    setting = json::parse(value);
  } catch (const json::exception&) {
    setting = value;  // a bare word: apparent, wrap, ...
  }
  if (key == "ao.preset") {
    // Written as its settings, not its name: the preset replaces them all.
    root["ao"] = json{{"preset", setting}};
  } else {
    json::json_pointer at;
    try {
      at = json::json_pointer(pointer);
    } catch (const json::exception&) {
      throw std::runtime_error(key + ": not a key of the scene");
    }
    if (key.empty() || !(root.contains(at) || appendsToList(root, at))) {
      throw std::runtime_error(unknownKeyMessage(root, key));
    }
    root[at] = setting;  // one past an array's end, the array grows by it
  }
  return parseScene(root.dump(), "setting " + key);
}

void saveSceneFile(const std::string& path, const Scene& scene) {
  base::requireExtension(path, ".json");
  base::AtomicFile file(path);
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
  if (!std::filesystem::is_regular_file(path, ec))
    throw std::runtime_error("cannot read scene file " + path + ": not a file");
  const std::optional<std::string> text = base::readTextFile(path);
  if (!text) throw std::runtime_error("cannot read scene file " + path);
  return parseScene(*text, path);
}

}  // namespace tp::scene
