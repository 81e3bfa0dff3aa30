# Included before a package's own CMake code (CMAKE_PROJECT_TOP_LEVEL_INCLUDES): find_package
# answers ament_cmake (and its parts) with launcher's own modules; anything else must be found
# in the workspace or the environment, or the build stops naming the package and what it
# needs. C++ targets stop it likewise. Every such message begins "launcher:", which the
# colcon wrapper turns into a located error.
set(LAUNCHER_AMENT_DIR "${CMAKE_CURRENT_LIST_DIR}")
set(_LAUNCHER_PROVIDED
  ament_cmake ament_cmake_core ament_cmake_auto ament_cmake_python ament_cmake_test
  ament_cmake_pytest ament_cmake_export_dependencies ament_cmake_libraries
  ament_lint_auto ament_lint_common ament_cmake_copyright ament_cmake_flake8
  ament_cmake_pep257 ament_cmake_xmllint ament_cmake_lint_cmake launch_testing_ament_cmake
  catkin)

macro(launcher_provide_dependency method name)
  if("${name}" IN_LIST _LAUNCHER_PROVIDED)
    include("${LAUNCHER_AMENT_DIR}/ament_cmake.cmake")
    set(${name}_FOUND TRUE)
  else()
    set(_launcher_args ${ARGN})
    set(_launcher_required FALSE)
    if("REQUIRED" IN_LIST _launcher_args)
      set(_launcher_required TRUE)
      list(REMOVE_ITEM _launcher_args REQUIRED)
    endif()
    find_package(${name} ${_launcher_args} QUIET BYPASS_PROVIDER)
    if(NOT ${name}_FOUND AND _launcher_required)
      message(FATAL_ERROR "launcher: find_package(${name}): package '${PROJECT_NAME}' needs "
        "'${name}', which is neither in the workspace nor a part of ament_cmake that "
        "launcher provides: ROS C++ libraries (rclcpp, message generation, Gazebo's C++ "
        "API) are not available; launcher builds packages of launch files, worlds, "
        "descriptions, hooks and Python nodes")
    endif()
  endif()
endmacro()
cmake_language(SET_DEPENDENCY_PROVIDER launcher_provide_dependency
  SUPPORTED_METHODS FIND_PACKAGE)

# A target that compiles nothing (its first argument IMPORTED, ALIAS, …: `compiles_nothing`)
# passes; any other stops the build.
function(_launcher_no_cxx command name first compiles_nothing)
  if(NOT "${first}" MATCHES "^(${compiles_nothing})$")
    message(FATAL_ERROR "launcher: ${command}(${name}): package '${PROJECT_NAME}' compiles "
      "C/C++, which launcher's builds do not (no compiler is used, and C++ nodes and Gazebo "
      "plugins do not run on launcher): write the node in Python (rclpy, rospy), or drive the "
      "sim through its services and Python plugins")
  endif()
endfunction()
function(add_executable name)
  _launcher_no_cxx(add_executable "${name}" "${ARGV1}" "IMPORTED|ALIAS")
  _add_executable(${ARGV})
endfunction()
function(add_library name)
  _launcher_no_cxx(add_library "${name}" "${ARGV1}" "IMPORTED|ALIAS|INTERFACE")
  _add_library(${ARGV})
endfunction()
