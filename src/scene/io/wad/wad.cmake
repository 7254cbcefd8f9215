# Doom WAD importer (included from src/scene/CMakeLists.txt).
target_sources(penumbra_scene PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/wad_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/map.cpp
  ${CMAKE_CURRENT_LIST_DIR}/textures.cpp
  ${CMAKE_CURRENT_LIST_DIR}/triangulate.cpp
  ${CMAKE_CURRENT_LIST_DIR}/wad_loader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/animation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/glow.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sector_light.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sky.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sprites.cpp
  ${CMAKE_CURRENT_LIST_DIR}/things.cpp
  ${CMAKE_CURRENT_LIST_DIR}/thing_placement.cpp)
