# The format dispatcher and Penumbra's own JSON scene files.
find_package(nlohmann_json CONFIG REQUIRED)  # Debian nlohmann-json3-dev
target_sources(penumbra_scene PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/load.cpp
  ${CMAKE_CURRENT_LIST_DIR}/scene_json.cpp)
target_link_libraries(penumbra_scene PRIVATE nlohmann_json::nlohmann_json)
