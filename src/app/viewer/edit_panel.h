// The panel's editing half: depth of field, the selected object (its material and position) and
// opening another scene. It only edits its state and raises requests; viewer_app applies them.
#pragma once

#include <cstdint>
#include <string>

#include "render/picking.h"
#include "render/view_settings.h"
#include "scene/light_edit.h"
#include "scene/scene.h"

namespace penumbra::viewer {

struct EditState {
    bool focusOnClick = false;           // the next left click sets the focus distance
    std::uint32_t object = kNoObject;    // the selection
    std::string objectName;
    std::uint32_t materialIndex = 0;
    Material material;                   // the selection's material as edited
    Vec3 position{0};                    // the selection's centre as edited (a group's pivot)
    // A sphere of a group (scene/sphere_groups.h) selects the whole group: it moves and turns.
    std::uint32_t group = kNoObject;
    Vec3 turnDegrees{0};                 // the turn being dialled in (about x, y, z through the pivot)
    // The Lights section: the scene's editable lights, the one shown and its values as edited.
    std::vector<EditableLight> lights;
    std::vector<std::string> lightNames;
    int lightChoice = 0;
    LightParams light;
    std::string openPath;                // the Open field
    std::string openMessage;             // the last Open error (one line)
    std::string addPath;                 // the Add model field
    std::string addMessage;              // what the last Add did (one line)
};

// What the user asked for this frame.
struct EditRequests {
    bool materialChanged = false;  // write state.material to scene.materials[state.materialIndex]
    bool moveObject = false;       // translate the selection to state.position
    bool turnGroup = false;        // turn the selected group by state.turnDegrees (then zero them)
    bool openScene = false;        // open state.openPath
    bool clearSelection = false;
    bool addModel = false;         // add the model at state.addPath in front of the camera
    bool lightChosen = false;      // load state.light from the light state.lightChoice names
    bool lightChanged = false;     // write state.light to that light
};

// Draws the sections into the current ImGui window.
void drawEditSections(ViewSettings& settings, EditState& state, EditRequests& requests);

// Fills the Lights section's list from the scene and loads the first light's values.
void loadLights(const Scene& scene, EditState& state);

// The centre of an object (a sphere's centre, a mesh's bounding-box centre).
Vec3 objectCentre(const Scene& scene, std::uint32_t object);
// The selection's centre: its group's pivot when it has one, else objectCentre.
Vec3 selectionCentre(const Scene& scene, const EditState& state);

}  // namespace penumbra::viewer
