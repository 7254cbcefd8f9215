# Environment maps (.hdr through stb_image, .exr through OpenEXR in penumbra_image) and the
# procedural sky (included from src/scene/CMakeLists.txt). Debian: libstb-dev, libopenexr-dev.
if(NOT TARGET PkgConfig::STB)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(STB REQUIRED IMPORTED_TARGET GLOBAL stb)
endif()
target_sources(penumbra_scene PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/../environment.cpp
  ${CMAKE_CURRENT_LIST_DIR}/env_load.cpp
  ${CMAKE_CURRENT_LIST_DIR}/env_sky.cpp
  ${CMAKE_CURRENT_LIST_DIR}/env_spec.cpp)
target_link_libraries(penumbra_scene PRIVATE PkgConfig::STB penumbra_image)
