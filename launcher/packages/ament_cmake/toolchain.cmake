# launcher's builds of ROS packages (colcon build, catkin_make): the packages users have for
# descriptions, worlds, launch files, hooks and Python nodes need no compiler, so none is
# looked for (project() enables C and C++ by default); a target that would compile is said
# by launcher_build.cmake, which this puts before every project's own code.
foreach(_launcher_lang C CXX)
  set(CMAKE_${_launcher_lang}_COMPILER_FORCED TRUE)
  set(CMAKE_${_launcher_lang}_COMPILER_ID_RUN TRUE)
  set(CMAKE_${_launcher_lang}_COMPILER_WORKS TRUE)
  set(CMAKE_${_launcher_lang}_COMPILER "${CMAKE_CURRENT_LIST_DIR}/no-compiler")
endforeach()
set(CMAKE_PROJECT_TOP_LEVEL_INCLUDES "${CMAKE_CURRENT_LIST_DIR}/launcher_build.cmake")
