// Built-in scenes, made in code so the binary needs no asset files.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace penumbra {

// The Cornell box from the measurements published by the Cornell Program of Computer Graphics,
// in metres, with its ceiling light.
Scene makeCornellBox();

// A closed box seen from inside: every wall has diffuse albedo `albedo` and emits `emission`
// toward the inside. Every pixel's exact value is emission / (1 - albedo) (the furnace test).
Scene makeFurnace(float albedo, Vec3 emission);

// The caffeine molecule's 24 atoms as CPK-coloured spheres over a coffee-brown plane, one sphere
// light, and a thin-lens camera focused on the molecule. The atoms form one sphere group, which
// the viewer moves and turns as one object.
Scene makeCaffeine();

// A room with mirror walls, a glass sphere, a semi-specular floor, a ceiling light and two soft
// bulbs around the Stanford bunny (Debian glmark2-data), or a stand-in mesh when it is missing.
Scene makeBunnyRoom();

// Rows of spheres sweeping roughness and metalness, plus glass and mirror, under a daylight sky.
Scene makeMaterialSpheres();

// A room for looking at the BVH: cubes far apart on one side, a dense cluster of small cubes on
// the other, and a slab laid diagonally across (bvh_lesson.cpp).
Scene makeBvhLesson();

// A 16 x 16 tile dungeon lit by wall torches (glowing panels) and the player's torch, with a
// phantom patrolling a corridor (an instance with a scene motion; scene/phantom.h switches it off)
// and a tile grid for the viewer's grid movement. Textured from Freedoom's freedoom1.wad
// (freedoomWadPath(), presets/dungeon_textures.h), or from `textureWad`; without it the dungeon
// is flat-coloured and a warning line says why.
Scene makeDungeon();
Scene makeDungeon(const std::filesystem::path& textureWad);

// Suzanne (Debian assimp-testmodels, read at run time) in the Cornell room without its blocks, as
// "Casually Pathtracing with WebGPU" renders it. Throws Error naming the package when the model
// is not installed.
Scene makeSuzanne();
const char* suzanneModelPath();

std::vector<std::string> presetNames();
// The names, comma-separated, for messages and help.
std::string presetList();
bool isPreset(const std::string& name);
// Throws UsageError listing the built-in names when `name` is not one.
Scene makePreset(const std::string& name);

}  // namespace penumbra
