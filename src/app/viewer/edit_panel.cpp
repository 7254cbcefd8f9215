#include "app/viewer/edit_panel.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstring>

#include "scene/sphere_groups.h"

namespace penumbra::viewer {
namespace {

void depthOfField(ViewSettings& s, EditState& state) {
    if (!ImGui::CollapsingHeader("Depth of field")) return;
    ImGui::SliderFloat("aperture radius (m)", &s.apertureRadius, 0.0f, 0.5f, "%.4f", ImGuiSliderFlags_Logarithmic);
    ImGui::SliderFloat("focus (m, 0: look-at)", &s.focusDistance, 0.0f, 100.0f, "%.3f",
                       ImGuiSliderFlags_Logarithmic);
    s.apertureRadius = std::max(s.apertureRadius, 0.0f);
    s.focusDistance = std::max(s.focusDistance, 0.0f);
    ImGui::Checkbox("focus on the next clicked point", &state.focusOnClick);
}

void selection(EditState& state, EditRequests& requests) {
    if (!ImGui::CollapsingHeader("Selection", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (state.object == kNoObject) {
        ImGui::TextWrapped("Left-click a surface to select its object (in free flight; walking, a click captures the mouse).");
        return;
    }
    ImGui::Text("%s", state.objectName.c_str());
    ImGui::SameLine();
    if (ImGui::Button("Deselect")) requests.clearSelection = true;
    Material& m = state.material;
    ImGui::Text("material %u '%s' (shared by every object that uses it)", state.materialIndex, m.name.c_str());
    bool changed = false;
    changed |= ImGui::ColorEdit3("base colour", &m.albedo.x);
    changed |= ImGui::SliderFloat("metallic", &m.metallic, 0.0f, 1.0f);
    changed |= ImGui::SliderFloat("roughness", &m.roughness, 0.0f, 1.0f);
    changed |= ImGui::SliderFloat("transmission", &m.transmission, 0.0f, 1.0f);
    changed |= ImGui::SliderFloat("ior", &m.ior, 1.0f, 3.0f);
    changed |= ImGui::DragFloat3("emission", &m.emission.x, 0.05f, 0.0f, 1000.0f);
    m.emission = Vec3{std::max(m.emission.x, 0.0f), std::max(m.emission.y, 0.0f), std::max(m.emission.z, 0.0f)};
    requests.materialChanged = changed;
    // Moving rebuilds the whole BVH, so it happens when the drag ends, not on every step.
    ImGui::DragFloat3(state.group == kNoObject ? "position" : "position (pivot)", &state.position.x, 0.01f);
    if (ImGui::IsItemDeactivatedAfterEdit()) requests.moveObject = true;
    if (state.group != kNoObject) {
        ImGui::DragFloat3("turn by (deg, x y z)", &state.turnDegrees.x, 0.5f, -180.0f, 180.0f, "%.1f");
        if (ImGui::IsItemDeactivatedAfterEdit()) requests.turnGroup = true;
        ImGui::TextDisabled("drag an atom to move the group; Shift+drag turns it");
    }
}

// Sliders for one light at a time. Intensity and colour change the light tables (lights are
// weighed by power) and position and radius the BVH, so an edit applies when the slider is let go.
void lights(EditState& state, EditRequests& requests) {
    if (state.lights.empty() || !ImGui::CollapsingHeader("Lights")) return;
    std::vector<const char*> names;
    for (const std::string& n : state.lightNames) names.push_back(n.c_str());
    if (ImGui::Combo("light", &state.lightChoice, names.data(), int(names.size()))) requests.lightChosen = true;
    LightParams& p = state.light;
    bool edited = false;
    auto released = [&] { edited |= ImGui::IsItemDeactivatedAfterEdit(); };
    if (p.hasPosition) {
        ImGui::DragFloat3("position (m)", &p.position.x, 0.01f);
        released();
    }
    ImGui::ColorEdit3("light colour", &p.color.x);
    released();
    ImGui::SliderFloat("intensity", &p.intensity, 0.0f, 1000.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
    released();
    ImGui::SliderFloat(p.hasPosition ? "radius (m, 0: a point)" : "angular radius (rad)", &p.radius, 0.0f,
                       p.hasPosition ? 2.0f : 0.785f, "%.4f", ImGuiSliderFlags_Logarithmic);
    released();
    if (p.isSpot) {
        ImGui::SliderFloat("spot angle (deg)", &p.spotDegrees, 0.1f, 90.0f, "%.1f");
        released();
    }
    requests.lightChanged = edited;
}

void openScene(EditState& state, EditRequests& requests) {
    if (!ImGui::CollapsingHeader("Scene file")) return;
    std::array<char, 1024> buffer{};
    std::strncpy(buffer.data(), state.openPath.c_str(), buffer.size() - 1);
    const bool entered = ImGui::InputText("path", buffer.data(), buffer.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    state.openPath = buffer.data();
    ImGui::SameLine();
    if (ImGui::Button("Open") || entered) requests.openScene = true;
    if (!state.openMessage.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", state.openMessage.c_str());
        ImGui::PopStyleColor();
    }
}

void addModel(EditState& state, EditRequests& requests) {
    if (!ImGui::CollapsingHeader("Add model")) return;
    std::array<char, 1024> buffer{};
    std::strncpy(buffer.data(), state.addPath.c_str(), buffer.size() - 1);
    const bool entered =
        ImGui::InputText("model path", buffer.data(), buffer.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    state.addPath = buffer.data();
    ImGui::SameLine();
    if (ImGui::Button("Add (M)") || entered) requests.addModel = true;
    ImGui::TextDisabled("placed in front of the camera as an instance: drag it, Shift+drag turns it");
    if (!state.addMessage.empty()) ImGui::TextWrapped("%s", state.addMessage.c_str());
}

}  // namespace

void drawEditSections(ViewSettings& settings, EditState& state, EditRequests& requests) {
    depthOfField(settings, state);
    selection(state, requests);
    lights(state, requests);
    addModel(state, requests);
    openScene(state, requests);
}

void loadLights(const Scene& scene, EditState& state) {
    state.lights = editableLights(scene);
    state.lightNames.clear();
    for (const EditableLight& l : state.lights) state.lightNames.push_back(lightName(scene, l));
    state.lightChoice = 0;
    if (!state.lights.empty()) state.light = lightParams(scene, state.lights[0]);
}

Vec3 selectionCentre(const Scene& scene, const EditState& state) {
    if (state.group < scene.sphereGroups.size()) return sphereGroupPivot(scene, state.group);
    return objectCentre(scene, state.object);
}

Vec3 objectCentre(const Scene& scene, std::uint32_t object) {
    if (!isObject(scene, object)) return Vec3{0};
    if (object >= scene.meshes.size()) return scene.spheres[object - scene.meshes.size()].center;
    Aabb box;
    for (const Vec3& p : scene.meshes[object].positions) box.grow(p);
    return box.empty() ? Vec3{0} : box.center();
}

}  // namespace penumbra::viewer
