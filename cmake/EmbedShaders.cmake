# voxgi_embed_shaders(TARGET <lib> INCLUDE_DIR <dir> SOURCES <stage files>)
# Each GLSL stage file is resolved (#include expanded, #line markers added), validated with
# glslangValidator (errors reported as file:line) and compiled into the library as a string.
function(voxgi_embed_shaders)
  cmake_parse_arguments(ARG "" "TARGET;INCLUDE_DIR" "SOURCES" ${ARGN})
  set(outputs)
  foreach(src ${ARG_SOURCES})
    file(RELATIVE_PATH name ${ARG_INCLUDE_DIR} ${src})
    string(MAKE_C_IDENTIFIER ${name} ident)
    set(out ${CMAKE_CURRENT_BINARY_DIR}/embedded/${ident}.cpp)
    file(GLOB_RECURSE includes ${ARG_INCLUDE_DIR}/shared/*.h ${ARG_INCLUDE_DIR}/*.glsl)
    add_custom_command(
      OUTPUT ${out}
      COMMAND voxgi_shader_embed --input ${src} --include-dir ${ARG_INCLUDE_DIR} --output ${out}
              --validator ${GLSLANG_VALIDATOR}
      DEPENDS ${src} ${includes} voxgi_shader_embed
      COMMENT "Embedding and validating ${name}" VERBATIM)
    list(APPEND outputs ${out})
  endforeach()
  target_sources(${ARG_TARGET} PRIVATE ${outputs})
endfunction()
