# What only the demo's build (CMake preset "demo", tools/demo.sh) does to
# compile the rockface program in less CPU time; the release build (CI:
# file by file, with the compiler cache) and the tests are not touched.
# Measured in docs/accuracy-cost.md, "The demo on a fresh machine".

# One precompiled header, built once (12 s of CPU) and used by the given
# libraries and the program: the standard library, Eigen, OpenCV and
# nlohmann-json headers their unity batches include. Parsing them cost ~5 s
# of CPU in each batch; with the header a batch of storage or the workflows
# compiles in 30-38 % less CPU.
# The compiler accepts the one header at -O1 to -O3 (all define
# __OPTIMIZE__); -Winvalid-pch in the preset says so if it ever refuses it.
function(rockface_demo_precompiled_headers)
  file(WRITE ${PROJECT_BINARY_DIR}/rockface_pch.cpp "// holds the demo's precompiled header\n")
  add_library(rockface_pch OBJECT ${PROJECT_BINARY_DIR}/rockface_pch.cpp)
  set(_includes ${OpenCV_INCLUDE_DIRS})
  target_link_libraries(rockface_pch PRIVATE Eigen3::Eigen nlohmann_json::nlohmann_json)
  target_include_directories(rockface_pch SYSTEM PRIVATE ${_includes})
  target_precompile_headers(rockface_pch PRIVATE
    <algorithm> <array> <cmath> <cstdint> <cstdio> <filesystem> <fstream> <functional> <iostream> <limits>
    <map> <memory> <numbers> <numeric> <optional> <set> <sstream> <string> <string_view> <utility> <vector>
    <Eigen/Dense> <opencv2/core.hpp> <opencv2/imgproc.hpp> <opencv2/imgcodecs.hpp> <opencv2/calib3d.hpp>
    <nlohmann/json.hpp>)
  foreach(target IN LISTS ARGN)
    target_precompile_headers(${target} REUSE_FROM rockface_pch)
    # Where the header's own includes are found, should the compiler ever
    # parse it as text (the Eigen-only core libraries do not link OpenCV).
    target_link_libraries(${target} PRIVATE $<BUILD_INTERFACE:Eigen3::Eigen>)
    target_include_directories(${target} SYSTEM PRIVATE ${_includes})
  endforeach()
endfunction()

# The libraries off the demo's hot path at -O1 instead of -O2 or -O3: the
# block and mechanics libraries (one block in the demo), storage, the field
# report, the office, the tablet UI, the program's workflows and its verbs
# (together about 1 % of the replay's CPU time, docs/accuracy-cost.md);
# their compile is ~20-30 % shorter. The same IEEE arithmetic (x86-64 SSE2,
# no fast-math, no contraction in ISO C++), so the same numbers; the
# release build keeps -O3 on the blocks' hot path (issue 17).
function(rockface_demo_cold_o1)
  foreach(target IN LISTS ARGN)
    target_compile_options(${target} PRIVATE -O1)
  endforeach()
endfunction()

# The libraries and programs defined under the given folders.
function(rockface_targets_in out)
  set(_all)
  foreach(dir IN LISTS ARGN)
    if(NOT IS_ABSOLUTE ${dir})
      set(dir ${PROJECT_SOURCE_DIR}/${dir})
    endif()
    if(NOT EXISTS ${dir}/CMakeLists.txt)
      continue()
    endif()
    get_property(_targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
    get_property(_subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
    if(_subdirs)
      rockface_targets_in(_below ${_subdirs})
      list(APPEND _targets ${_below})
    endif()
    list(APPEND _all ${_targets})
  endforeach()
  set(${out} ${_all} PARENT_SCOPE)
endfunction()
