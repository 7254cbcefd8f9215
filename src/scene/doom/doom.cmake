# Doom levels that play: line specials, sector movers, the level's tic clock (included from
# src/scene/CMakeLists.txt).
target_sources(penumbra_scene PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/sector_movers.cpp
  ${CMAKE_CURRENT_LIST_DIR}/line_specials.cpp
  ${CMAKE_CURRENT_LIST_DIR}/level.cpp
  ${CMAKE_CURRENT_LIST_DIR}/level_looks.cpp
  ${CMAKE_CURRENT_LIST_DIR}/light_specials.cpp)
