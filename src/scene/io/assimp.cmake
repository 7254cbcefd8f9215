# Models through Assimp (FBX, Collada, 3DS, STL, ...; included from src/scene/CMakeLists.txt).
# Debian libassimp-dev.
find_package(assimp CONFIG REQUIRED)
target_sources(penumbra_scene PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/assimp_loader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/assimp_materials.cpp)
target_link_libraries(penumbra_scene PRIVATE assimp::assimp)
