# TIFF textures and environment maps (included from src/scene/CMakeLists.txt). Debian libtiff-dev.
find_package(TIFF REQUIRED)
target_sources(penumbra_scene PRIVATE ${CMAKE_CURRENT_LIST_DIR}/tiff_io.cpp)
target_link_libraries(penumbra_scene PRIVATE TIFF::TIFF)
