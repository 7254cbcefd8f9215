# Stanford PLY importer (included from src/scene/CMakeLists.txt); zlib (Debian zlib1g-dev) reads .ply.gz.
find_package(ZLIB REQUIRED)
target_sources(penumbra_scene PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/ply.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ply_header.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gzip.cpp)
target_link_libraries(penumbra_scene PRIVATE ZLIB::ZLIB)
