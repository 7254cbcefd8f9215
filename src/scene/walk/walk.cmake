# Walking: collision lines and Doom's player movement (included from src/scene/CMakeLists.txt).
target_sources(penumbra_scene PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/walk_map.cpp
  ${CMAKE_CURRENT_LIST_DIR}/walk_physics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/wad_walk_map.cpp)
