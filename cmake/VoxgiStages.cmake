# Every stage's files, found by convention from the stage list (docs/architecture.md, "Adding a
# stage"). A stage `owner/name` declared by VOXGI_STAGE in common/stages.inc or the lists it
# includes has, with <dir> = "<owner>/" for a technique's stage and "" for a shared one:
#
#   cpu/<dir><name>.cpp               its CPU twin (voxgi_cpu)
#   gpu/<dir><name>.cpp               its GPU twin (voxgi_gpu)
#   shaders/<dir><name>[_*].<stage>   its GLSL files (.vert .geom .frag .comp), validated, embedded
#   tests/<dir><name>_test.cpp        its tests (voxgi_stage_tests)
#   docs/stages/<dir><name>.md        its page
#
# and, when it has them, its host preparation common/<dir><name>.cpp (voxgi_common) and its
# shared kernel shaders/shared/<dir><name>_kernel.h (included by the files above, so a missing one
# fails the build naming it). A missing file stops the configure step with a message naming the
# file and the stage.

# VOXGI_STAGES: "owner/name" for every declared stage, in the order of the lists.
function(voxgi_read_stages)
  set(root ${PROJECT_SOURCE_DIR}/common)
  file(STRINGS ${root}/stages.inc includes REGEX "^#include \"common/.*stages\\.inc\"")
  set(lists)
  foreach(line ${includes})
    string(REGEX REPLACE "^#include \"common/(.*)\"" "\\1" list "${line}")
    list(APPEND lists ${root}/${list})
  endforeach()
  set(stages)
  foreach(list ${lists})
    set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${list})
    # clang-format may wrap a declaration after its opening parenthesis.
    file(READ ${list} text)
    string(REGEX MATCHALL "\nVOXGI_STAGE\\([ \n]*[a-z0-9_]+,[ \n]*[a-z0-9_]+," declarations
           "\n${text}")
    foreach(declaration ${declarations})
      string(REGEX REPLACE "[ \n]" "" declaration "${declaration}")
      string(REGEX MATCH "^VOXGI_STAGE\\(([a-z0-9_]+),([a-z0-9_]+)," match "${declaration}")
      list(APPEND stages "${CMAKE_MATCH_1}/${CMAKE_MATCH_2}")
    endforeach()
  endforeach()
  set_property(GLOBAL PROPERTY VOXGI_STAGES ${stages})
endfunction()

# The path of `stage`'s file in `folder` with `suffix`: cpu/lpv/inject.cpp, cpu/voxelize.cpp.
function(voxgi_stage_path out folder stage suffix)
  string(REPLACE "/" ";" parts ${stage})
  list(GET parts 0 owner)
  list(GET parts 1 name)
  if(owner STREQUAL "common")
    set(${out} ${folder}/${name}${suffix} PARENT_SCOPE)
  else()
    set(${out} ${folder}/${owner}/${name}${suffix} PARENT_SCOPE)
  endif()
endfunction()

# Every stage's file in `folder` with `suffix`, as absolute paths in `out`; a stage without one
# stops the configure step unless OPTIONAL.
function(voxgi_stage_files out folder suffix)
  cmake_parse_arguments(ARG "OPTIONAL" "" "" ${ARGN})
  get_property(stages GLOBAL PROPERTY VOXGI_STAGES)
  set(files)
  foreach(stage ${stages})
    voxgi_stage_path(path ${folder} ${stage} ${suffix})
    if(EXISTS ${PROJECT_SOURCE_DIR}/${path})
      list(APPEND files ${PROJECT_SOURCE_DIR}/${path})
    elseif(NOT ARG_OPTIONAL)
      message(FATAL_ERROR "stage ${stage} has no ${path} (docs/architecture.md, \"Adding a stage\")")
    endif()
  endforeach()
  set(${out} ${files} PARENT_SCOPE)
endfunction()

# The GLSL files of every stage, relative to shaders/: each file in shaders/ belongs to the stage
# of its folder whose name it is or starts with followed by "_" (the longest such name), or, a pass
# several of a technique's stages run, to the GPU file of the same name (shaders/T/F.comp,
# gpu/T/F.cpp); every stage has at least one file.
function(voxgi_stage_shaders out)
  get_property(stages GLOBAL PROPERTY VOXGI_STAGES)
  set(folder ${PROJECT_SOURCE_DIR}/shaders)
  file(GLOB_RECURSE on_disk RELATIVE ${folder} CONFIGURE_DEPENDS ${folder}/*.vert ${folder}/*.geom
       ${folder}/*.frag ${folder}/*.comp)
  list(SORT on_disk)
  set(claimed)
  foreach(shader ${on_disk})
    get_filename_component(dir ${shader} DIRECTORY)
    get_filename_component(file ${shader} NAME_WE)
    if(dir STREQUAL "")
      set(dir common)
    endif()
    set(best "")
    foreach(stage ${stages})
      string(REPLACE "/" ";" parts ${stage})
      list(GET parts 0 owner)
      list(GET parts 1 name)
      string(LENGTH "${name}" length)
      string(LENGTH "${best}" bestLength)
      if(owner STREQUAL dir AND (file STREQUAL name OR file MATCHES "^${name}_")
         AND length GREATER bestLength)
        set(best ${name})
      endif()
    endforeach()
    if(best STREQUAL "")
      # A pass that several of a technique's stages run is named after the GPU file that runs it
      # (shaders/svo/bricks.comp, gpu/svo/bricks.cpp).
      get_filename_component(folder_of_dir ${shader} DIRECTORY)
      if(NOT EXISTS ${PROJECT_SOURCE_DIR}/gpu/${folder_of_dir}/${file}.cpp OR dir STREQUAL common)
        message(FATAL_ERROR "shaders/${shader} belongs to no stage of ${dir} and to no file "
                            "gpu/${folder_of_dir}/${file}.cpp: a stage's GLSL files are named after "
                            "it, a pass several stages run after the GPU file that runs it "
                            "(docs/architecture.md, \"Adding a stage\")")
      endif()
    else()
      list(APPEND claimed ${dir}/${best})
    endif()
  endforeach()
  foreach(stage ${stages})
    if(NOT stage IN_LIST claimed)
      voxgi_stage_path(path shaders ${stage} "")
      message(FATAL_ERROR "stage ${stage} has no GLSL file ${path}.comp (or .vert and .frag, or "
                          "${path}_*) (docs/architecture.md, \"Adding a stage\")")
    endif()
  endforeach()
  set(${out} ${on_disk} PARENT_SCOPE)
endfunction()

# The files a stage has but no target builds: its page.
function(voxgi_check_stage_docs)
  voxgi_stage_files(pages docs/stages .md)
endfunction()
