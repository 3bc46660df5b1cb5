#include "viewer/view_panel.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <string_view>

#include "scene/scene_keys.hpp"
#include "shading/water_model.hpp"
#include "sim/water_params.hpp"

namespace tp::app {
namespace {

// A drag moves a number by this fraction of its size per pixel (and at least
// kMinDragStep): fine enough for a radius, quick enough for a far plane.
constexpr float kDragFraction = 0.005f;
constexpr float kMinDragStep = 1e-3f;
constexpr float kCountDragSpeed = 0.2f;
constexpr float kPanelMargin = 8.0f;
const ImVec4 kErrorColor{1.0f, 0.45f, 0.4f, 1.0f};

// The keys the renderer takes live (from the next frame, nothing rebuilt).
bool takenLive(std::string_view path) {
  return path.starts_with("camera.") || path == "water.wave_speed" || path == "water.damping" ||
         path == "water.grid_damping" || path == "water.max_slope" || path == "water.sphere_forcing" ||
         (path.starts_with("spheres[") && path.ends_with("].center"));
}

// The widgets of one object of the scene file (scene_keys.hpp's visitor):
// each key a widget labelled with its name, edits made in place.
class PanelEditor {
 public:
  explicit PanelEditor(std::string path) : path_(std::move(path)) {}

  void number(const char* key, float& value) {
    const float speed = std::max(std::abs(value) * kDragFraction, kMinDragStep);
    edited(key, ImGui::DragFloat(key, &value, speed, 0.0f, 0.0f, "%.5g"));
  }
  void count(const char* key, unsigned& value) {
    edited(key, ImGui::DragScalar(key, ImGuiDataType_U32, &value, kCountDragSpeed));
  }
  void vec3(const char* key, glm::vec3& value) {
    const float speed =
        std::max(std::max({std::abs(value.x), std::abs(value.y), std::abs(value.z)}) * kDragFraction, kMinDragStep);
    edited(key, ImGui::DragFloat3(key, &value.x, speed, 0.0f, 0.0f, "%.4g"));
  }
  void color(const char* key, glm::vec3& value) {
    edited(key, ImGui::ColorEdit3(key, &value.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR));
  }
  void flag(const char* key, bool& value) { done(ImGui::Checkbox(key, &value)); }
  void text(const char* key, std::string& value) {
    ImGui::InputText(key, &value);
    done(ImGui::IsItemDeactivatedAfterEdit());
  }
  void choice(const char* key, std::string& value, const std::vector<std::string>& allowed) {
    if (!ImGui::BeginCombo(key, value.c_str())) return;
    for (const std::string& option : allowed) {
      if (ImGui::Selectable(option.c_str(), option == value) && option != value) {
        value = option;
        done(true);
      }
    }
    ImGui::EndCombo();
  }
  // An AO preset replaces every AO setting: it shows which one they now are.
  void preset(const char* key, scene::Ao& ao) {
    std::string now = "(custom)";
    for (const std::string& name : scene::choices::kAoPreset) {
      if (scene::aoPreset(name) == ao) now = name;
    }
    std::string chosen = now;
    choice(key, chosen, scene::choices::kAoPreset);
    if (chosen != now) ao = scene::aoPreset(chosen);
  }
  template <typename F>
  void object(const char* key, F&& fields) {
    if (!ImGui::CollapsingHeader(key)) return;
    ImGui::PushID(key);
    PanelEditor child(join(key));
    fields(child);
    commit_ |= child.commit_;
    ImGui::PopID();
  }
  template <typename T, typename F>
  void objects(const char* key, std::vector<T>& values, F&& fields) {
    const std::string label = std::string(key) + " (" + std::to_string(values.size()) + ")";
    const bool top = path_.empty();
    if (top ? !ImGui::CollapsingHeader(label.c_str()) : !ImGui::TreeNode(key, "%s", label.c_str())) return;
    ImGui::PushID(key);
    for (size_t i = 0; i < values.size(); ++i) {
      const std::string name = std::string(key) + "[" + std::to_string(i) + "]";
      ImGui::PushID(int(i));
      if (ImGui::TreeNode(name.c_str())) {
        PanelEditor child(path_.empty() ? name : path_ + "." + name);
        fields(child, values[i]);
        commit_ |= child.commit_;
        ImGui::TreePop();
      }
      ImGui::PopID();
    }
    ImGui::PopID();
    if (!top) ImGui::TreePop();
  }

  bool committed() const { return commit_; }

 private:
  std::string join(const char* key) const { return path_.empty() ? key : path_ + "." + key; }
  // A drag or field: live keys as they move, the others when let go.
  void edited(const char* key, bool changed) {
    done(takenLive(join(key)) ? changed : ImGui::IsItemDeactivatedAfterEdit());
  }
  void done(bool finished) { commit_ |= finished; }

  std::string path_;
  bool commit_ = false;
};

void showWater(const scene::Water& water) {
  if (!water.enabled) {
    ImGui::TextUnformatted("no water");
    return;
  }
  try {
    const sim::WaterParams params = sim::waterParams(water);
    const uint32_t substeps = sim::waterSubsteps(water);
    const double dt = sim::waterStep(water);
    ImGui::Text("%u substeps per frame, dt %.3g ms", substeps, dt * 1e3);
    ImGui::Text("lambda = c dt / h = %.4f (bound %.4f%s)", params.lambda(dt), sim::lambdaBound(params),
                params.maxSlope > 0.0 ? ", with the slope limiter" : ", 1/sqrt 2");
  } catch (const std::exception& e) {
    ImGui::TextColored(kErrorColor, "%s", e.what());
  }
}

void showProfile(const render::RenderedFrame& frame) {
  ImGui::Text("%zu passes, %llu dispatches, %llu draws, %llu workgroups%s", frame.passes.size(),
              static_cast<unsigned long long>(frame.counts.dispatches),
              static_cast<unsigned long long>(frame.counts.draws),
              static_cast<unsigned long long>(frame.counts.workgroups), frame.waterAsleep ? "; water asleep" : "");
  if (!ImGui::BeginTable("passes", 5, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) return;
  for (const char* heading : {"pass", "GPU ms", "dispatches", "draws", "workgroups"}) ImGui::TableSetupColumn(heading);
  ImGui::TableHeadersRow();
  double total = 0.0;
  for (const render::RecordedPass& pass : frame.passes) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(pass.name.c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%.2f", pass.milliseconds);
    ImGui::TableNextColumn();
    ImGui::Text("%llu", static_cast<unsigned long long>(pass.counts.dispatches));
    ImGui::TableNextColumn();
    ImGui::Text("%llu", static_cast<unsigned long long>(pass.counts.draws));
    ImGui::TableNextColumn();
    ImGui::Text("%llu", static_cast<unsigned long long>(pass.counts.workgroups));
    if (std::isfinite(pass.milliseconds)) total += pass.milliseconds;
  }
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted("total");
  ImGui::TableNextColumn();
  ImGui::Text("%.2f", total);
  ImGui::EndTable();
}

}  // namespace

PanelPlacement panelPlacement(float width, float height) {
  const float third = width / 3.0f;
  return {.x = kPanelMargin,
          .y = kPanelMargin,
          .width = std::clamp(third, kPanelMinWidth, kPanelMaxWidth),
          .height = std::max(height - 2.0f * kPanelMargin, 0.0f),
          .collapsed = third < kPanelMinWidth};
}

PanelRequests ViewPanel::draw(const scene::Scene& scene, const PanelStatus& status) {
  PanelRequests out;
  // While a widget is held, the draft keeps its edit; otherwise it follows
  // the scene (the mouse orbits the camera, a click adds a drop).
  if (!ImGui::IsAnyItemActive()) draft_ = scene;
  const PanelPlacement place = panelPlacement(ImGui::GetIO().DisplaySize.x, ImGui::GetIO().DisplaySize.y);
  ImGui::SetNextWindowPos(ImVec2(place.x, place.y), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(place.width, place.height), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowCollapsed(place.collapsed, ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("tidepool (F1 hides)")) {
    ImGui::End();
    return out;
  }
  ImGui::Text("frame %u%s, %.1f fps", status.frame, status.paused ? " (paused)" : "", status.fps);
  if (status.last) ImGui::Text("rendered at %ux%u", status.last->width, status.last->height);
  if (ImGui::Button(status.paused ? "Run" : "Pause")) out.commands.push_back(command::TogglePause{});
  ImGui::SameLine();
  if (ImGui::Button("Step")) out.commands.push_back(command::Step{});
  ImGui::SameLine();
  if (ImGui::Button("Reset camera")) out.commands.push_back(command::ResetCamera{});
  ImGui::SameLine();
  if (ImGui::Button("Save frame")) out.commands.push_back(command::Save{});
  ImGui::SameLine();
  if (ImGui::Button("Reload shaders")) out.commands.push_back(command::ReloadShaders{});
  ImGui::InputTextWithHint("##scene path", "scene-NNNN.json in the save folder", &scenePath_);
  ImGui::SameLine();
  if (ImGui::Button("Save scene")) out.commands.push_back(command::SaveScene{scenePath_});
  if (!status.message.empty()) {
    if (status.messageIsError)
      ImGui::TextColored(kErrorColor, "%s", status.message.c_str());
    else
      ImGui::TextWrapped("%s", status.message.c_str());
  }
  if (status.shaderErrors && !status.shaderErrors->empty()) {
    ImGui::TextColored(kErrorColor, "shader reload failed; the last good code runs:");
    for (const std::string& error : *status.shaderErrors) ImGui::TextWrapped("%s", error.c_str());
  }
  if (ImGui::CollapsingHeader("GPU passes", ImGuiTreeNodeFlags_DefaultOpen) && status.last) showProfile(*status.last);
  if (ImGui::CollapsingHeader("water stability", ImGuiTreeNodeFlags_DefaultOpen)) showWater(draft_.water);
  PanelEditor editor("");
  scene::visitScene(editor, draft_);
  if (editor.committed() && !(draft_ == scene)) out.scene = draft_;
  ImGui::End();
  return out;
}

}  // namespace tp::app
