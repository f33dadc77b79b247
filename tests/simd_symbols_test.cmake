# SimdSymbols.WideLanesShareNoInlineCode (tests/CMakeLists.txt): the objects built with -mavx2 or
# -mavx512f may define, besides local symbols, only their own entry points and template code whose
# name carries their instruction set. Any other global or weak definition (an inline function of
# the standard library, glm, or xsimd's SSE kernels) could be the copy the linker keeps for the
# whole program, and a CPU without that instruction set would then fault in code that never asked
# for it.
#   cmake -DNM=nm "-DOBJECTS=a.o|b.o" -P simd_symbols_test.cmake
string(REPLACE "|" ";" objects "${OBJECTS}")
set(shared "")
foreach(object IN LISTS objects)
  if(object MATCHES "avx512")
    set(isa "avx512")
  elseif(object MATCHES "avx2")
    set(isa "avx2")
  else()
    message(FATAL_ERROR "${object}: not one of the wide lanes' objects")
  endif()
  execute_process(COMMAND ${NM} -C --defined-only ${object} OUTPUT_VARIABLE symbols
                  RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${NM} failed on ${object}")
  endif()
  string(REPLACE "\n" ";" lines "${symbols}")
  foreach(line IN LISTS lines)
    # Upper-case types are global, u, v and w weak or unique; lower-case others are local.
    if(NOT line MATCHES "^[0-9a-f]+ ([A-Zuvw]) (.*)$")
      continue()
    endif()
    set(name "${CMAKE_MATCH_2}")
    if(name MATCHES "^voxgi::cpu::lpv_lanes::(propagate|visibility)Rows(Avx2|Avx512)\\("
       OR name MATCHES "^voxgi::cpu::cone_lanes::marchCones(Avx2|Avx512)\\("
       OR name MATCHES "^voxgi::cpu::shadow_lanes::marchShadowRays(Avx2|Avx512)\\("
       OR name MATCHES "^DW\\.ref\\.__gxx_personality_v0$" OR name MATCHES "${isa}")
      continue()
    endif()
    list(APPEND shared "${object}: ${name}")
  endforeach()
endforeach()
if(shared)
  string(REPLACE ";" "\n  " shared "${shared}")
  message(FATAL_ERROR "inline code defined where another unit may link it:\n  ${shared}")
endif()
message(STATUS "the wide lanes define only their entry points")
