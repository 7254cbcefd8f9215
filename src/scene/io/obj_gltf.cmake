# OBJ/MTL and glTF importers plus texture decoding (included from src/scene/CMakeLists.txt).
# Debian packages: libtinyobjloader-dev, libtinygltf-dev (built with its own stb_image and JSON;
# we install our own image loader and file-system callbacks), libstb-dev.
find_package(tinyobjloader CONFIG REQUIRED)
find_package(TinyGLTF CONFIG REQUIRED)  # exports TinyGLTF::TinyGLTF (libtinygltf.so)
if(NOT TARGET PkgConfig::STB)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(STB REQUIRED IMPORTED_TARGET GLOBAL stb)
endif()

target_sources(penumbra_scene PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/obj.cpp
  ${CMAKE_CURRENT_LIST_DIR}/obj_parse.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gltf.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gltf_accessor.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gltf_model.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gltf_node.cpp
  ${CMAKE_CURRENT_LIST_DIR}/texture_io.cpp
  ${CMAKE_CURRENT_LIST_DIR}/normals.cpp)
target_link_libraries(penumbra_scene PRIVATE
  tinyobjloader::tinyobjloader TinyGLTF::TinyGLTF PkgConfig::STB)
