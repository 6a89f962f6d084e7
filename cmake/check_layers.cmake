# cmake -DKIND=core|widgets -DROOT=<dir> -P check_layers.cmake
# Fails when a file of a lower group includes a header of a higher one. A group may include its own
# and lower ranks; groups of one rank do not include each other.
#
# core/ (KIND=core; files under include/mocap/<group>/ and src/<group>/, includes "mocap/<group>/"):
#   0 base · 1 model · 2 math · 3 io, video · 4 cleaning (with cleaning/fill) · 5 tracking, layout, deform ·
#   6 evaluation, stream · 7 batch
# math (numerics on plain arrays) sits below io because a writer may use it (the FBX writer
# reduces its curves' keys).
# cleaning sits below tracking, layout and deform because they use its head stabilization and
# smoothers; nothing in cleaning needs them. batch (archives cleaned with a preset, and their
# reports) sits on top so it may run any method below. stream (live UDP senders) takes solved
# weights and takes as they come, beside evaluation.
#
# widgets/ (KIND=widgets; files under <group>/, includes "<group>/"):
#   0 document · 1 commands · 2 views · 3 models, dialogs · 4 actions · 5 panels
# The document (session, take, models of the face mesh and the solve) knows no widget; commands edit
# the document; views draw it and know no panel; item models and dialogs may use views (colours,
# plots, progress rows); actions open dialogs; panels may trigger actions. Nothing in widgets/ includes the application (app/, main_window.h).
if(KIND STREQUAL "core")
  set(ranks base 0 model 1 math 2 io 3 video 3 cleaning 4 tracking 5 layout 5 deform 5 evaluation 6 stream 6 batch 7)
  set(globs "include/mocap/*.h" "src/*.cpp")
  set(file_group "^(include/mocap|src)/([a-z_]+)/")
  set(include_group "^#include \"mocap/([a-z_]+)/")
  set(include_lines "^#include \"mocap/")
elseif(KIND STREQUAL "widgets")
  set(ranks document 0 commands 1 views 2 models 3 dialogs 3 actions 4 panels 5)
  set(globs "*.h" "*.cpp")
  set(file_group "^()([a-z_]+)/")
  set(include_group "^#include \"([a-z_]+)/")
  set(include_lines "^#include \"([a-z_]+/|main_window\\.h|app/)")
else()
  message(FATAL_ERROR "check_layers: pass -DKIND=core or -DKIND=widgets")
endif()
if(NOT ROOT)
  message(FATAL_ERROR "check_layers: pass -DROOT=<directory>")
endif()
while(ranks)
  list(POP_FRONT ranks group rank)
  set(rank_${group} ${rank})
endwhile()

get_filename_component(ROOT "${ROOT}" ABSOLUTE)
set(patterns)
foreach(glob IN LISTS globs)
  list(APPEND patterns "${ROOT}/${glob}")
endforeach()
file(GLOB_RECURSE files RELATIVE "${ROOT}" ${patterns})
set(violations 0)
macro(violation text)
  message(SEND_ERROR "${text}")
  math(EXPR violations "${violations} + 1")
endmacro()
foreach(file IN LISTS files)
  if(NOT file MATCHES "${file_group}")
    if(KIND STREQUAL "widgets")
      continue()  # widgets/CMakeLists.txt and the like sit beside the groups
    endif()
    violation("${file}: not in a group folder")
    continue()
  endif()
  set(group "${CMAKE_MATCH_2}")
  if(NOT DEFINED rank_${group})
    violation("${file}: unknown group '${group}'")
    continue()
  endif()
  file(STRINGS "${ROOT}/${file}" includes REGEX "${include_lines}")
  foreach(line IN LISTS includes)
    if(line MATCHES "main_window\\.h|\"app/")
      violation("${file} (${group}) includes the application: ${line}")
      continue()
    endif()
    if(NOT line MATCHES "${include_group}")
      violation("${file}: ${line} names no group")
      continue()
    endif()
    set(other "${CMAKE_MATCH_1}")
    if(other STREQUAL group)
      continue()
    endif()
    if(NOT DEFINED rank_${other})
      if(KIND STREQUAL "widgets")
        continue()  # the core's headers ("mocap/…") and other libraries' folders
      endif()
      violation("${file} (${group}) includes the unknown group ${other}: ${line}")
    elseif(NOT rank_${other} LESS rank_${group})
      violation("${file} (${group}) includes ${other}: ${line}")
    endif()
  endforeach()
endforeach()
if(violations GREATER 0)
  message(FATAL_ERROR "check_layers: ${violations} include(s) break the ${KIND} layering")
endif()
list(LENGTH files count)
message(STATUS "check_layers: ${count} ${KIND} files, layering holds")
