# The viewer's input script (--script): GLFW's header gives the key codes, nothing more of the viewer.
if(PENUMBRA_VIEWER)
  penumbra_fuzz_target(input_script LIBS penumbra_core)
  foreach(target replay_input_script fuzz_input_script)
    if(TARGET ${target})
      target_sources(${target} PRIVATE ${CMAKE_SOURCE_DIR}/src/interact/input_script.cpp
                     ${CMAKE_SOURCE_DIR}/src/interact/controls.cpp)
    endif()
  endforeach()
endif()
