# Who may include whom (docs/architecture.md, "Layout"), checked at configure time so that a
# forbidden include stops the build naming the file and the include:
#
#   - a technique's files (<top>/T/ for top in common cpu gpu validation tests, shaders/T/,
#     shaders/shared/T/) include no other technique's files;
#   - the cone library's (common/cone/, cpu/cone/, gpu/cone/, shaders/shared/cone/, tests/cone/)
#     include no technique's files: vct, lpv and svo depend on it, never the reverse;
#   - the generic code (the rest of common/, cpu/, gpu/, validation/, shaders/) includes no
#     technique's files, but for the registries that list every technique by design.
#
# An include is resolved as the compilers do: next to the including file, from the source root
# (C++), or from shaders/ (GLSL); one that resolves to no file of the tree (a system or generated
# header) is not checked.

# The registries: the one place each list of techniques lives.
set(VOXGI_INCLUDE_REGISTRIES common/stages.inc validation/comparisons.inc)

# `out`: the technique or library folder `path` (relative to the source root) lies in, "" for
# generic code.
function(voxgi_include_owner out path techniques)
  set(owner "")
  set(folder "")
  # One MATCHES an if(): CMake evaluates every operand of an OR, and each match resets
  # CMAKE_MATCH_<n>.
  if(path MATCHES "^(common|cpu|gpu|validation|tests)/([a-z0-9_]+)/")
    set(folder ${CMAKE_MATCH_2})
  elseif(path MATCHES "^shaders/shared/([a-z0-9_]+)/")
    set(folder ${CMAKE_MATCH_1})
  elseif(path MATCHES "^shaders/([a-z0-9_]+)/")
    set(folder ${CMAKE_MATCH_1})
  endif()
  if(folder IN_LIST techniques OR folder STREQUAL "cone")
    set(owner ${folder})
  endif()
  set(${out} "${owner}" PARENT_SCOPE)
endfunction()

function(voxgi_check_includes)
  get_property(stages GLOBAL PROPERTY VOXGI_STAGES)
  set(techniques)
  foreach(stage ${stages})
    string(REGEX REPLACE "/.*" "" owner ${stage})
    if(NOT owner STREQUAL "common" AND NOT owner IN_LIST techniques)
      list(APPEND techniques ${owner})
    endif()
  endforeach()
  set(root ${PROJECT_SOURCE_DIR})
  file(GLOB_RECURSE sources RELATIVE ${root} CONFIGURE_DEPENDS
       ${root}/common/*.h ${root}/common/*.cpp ${root}/common/*.inc
       ${root}/cpu/*.h ${root}/cpu/*.cpp ${root}/gpu/*.h ${root}/gpu/*.cpp ${root}/gpu/*.inc
       ${root}/validation/*.h ${root}/validation/*.cpp ${root}/validation/*.inc
       ${root}/tests/*.h ${root}/tests/*.cpp
       ${root}/shaders/*.h ${root}/shaders/*.glsl ${root}/shaders/*.comp ${root}/shaders/*.vert
       ${root}/shaders/*.geom ${root}/shaders/*.frag)
  foreach(source ${sources})
    voxgi_include_owner(from ${source} "${techniques}")
    if(from STREQUAL "" AND (source MATCHES "^tests/" OR source IN_LIST VOXGI_INCLUDE_REGISTRIES))
      continue()  # the generic tests and the registries may name any technique
    endif()
    file(STRINGS ${root}/${source} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    get_filename_component(dir ${source} DIRECTORY)
    foreach(line ${includes})
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" include "${line}")
      set(target "")
      foreach(candidate ${dir}/${include} ${include} shaders/${include})
        cmake_path(NORMAL_PATH candidate)
        if(EXISTS ${root}/${candidate} AND NOT IS_DIRECTORY ${root}/${candidate})
          set(target ${candidate})
          break()
        endif()
      endforeach()
      if(target STREQUAL "")
        continue()
      endif()
      voxgi_include_owner(to ${target} "${techniques}")
      if(to STREQUAL "" OR to STREQUAL from OR to STREQUAL "cone")
        continue()
      endif()
      if(from STREQUAL "")
        set(rule "generic code includes no technique's files but for the registries")
      elseif(from STREQUAL "cone")
        set(rule "the cone library includes no technique's files")
      else()
        set(rule "a technique includes no other technique's files")
      endif()
      message(FATAL_ERROR "${source} includes ${target}: ${rule} (docs/architecture.md, "
                          "\"Layout\"; what several techniques share belongs in the cone library "
                          "or at the folders' tops)")
    endforeach()
  endforeach()
endfunction()
