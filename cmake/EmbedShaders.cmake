# GLSL ES 3.00 shaders as files under src/render/shaders/, checked and embedded at build time.
#
# Included from CMake (src/render/CMakeLists.txt), it defines trailray_embed_shaders(). Run as a
# script (cmake -P) by the build, it does one of two steps:
#   MODE=validate  expands the `#include "snippet.glsl"` lines of one .vert/.frag file, writes
#                  the expanded source and its line map (expanded line -> file and line), and runs
#                  glslangValidator on it. Errors are reported against the original files
#                  ("src/render/shaders/sky.frag:12: ERROR: ..."), and fail the build.
#   MODE=embed     writes one .cpp holding every expanded source (as byte arrays, so no shader
#                  text can break the C++) and its line map, read at run time through
#                  render/gl/shader_source.hpp.
# Expanding at build time means the validator checks exactly the text the driver will compile,
# and the line map lets run-time driver errors name the snippet file a line came from.
#
# A snippet is included once per shader (a second `#include` of it is dropped, like `#pragma
# once`); snippets may include snippets; only a stage file starts with `#version`.

if(NOT CMAKE_SCRIPT_MODE_FILE)
  set(_TRAILRAY_EMBED_SHADERS_SCRIPT ${CMAKE_CURRENT_LIST_FILE})

  # trailray_embed_shaders(<out_var> SHADER_DIR <dir> VALIDATOR <glslangValidator>)
  # Sets <out_var> to the generated .cpp to compile into the library. Every .vert and .frag under
  # SHADER_DIR gets a validation step of its own; a shader error fails the build.
  function(trailray_embed_shaders out_var)
    cmake_parse_arguments(PARSE_ARGV 1 ARG "" "SHADER_DIR;VALIDATOR" "")
    file(GLOB_RECURSE stage_files CONFIGURE_DEPENDS ${ARG_SHADER_DIR}/*.vert ${ARG_SHADER_DIR}/*.frag)
    file(GLOB_RECURSE snippet_files CONFIGURE_DEPENDS ${ARG_SHADER_DIR}/*.glsl)
    list(SORT stage_files)
    set(work_dir ${CMAKE_CURRENT_BINARY_DIR}/shaders)
    set(expanded_files "")
    set(names "")
    foreach(stage_file ${stage_files})
      file(RELATIVE_PATH name ${ARG_SHADER_DIR} ${stage_file})
      # Any snippet may be included by any shader: depending on all of them is simple and cheap.
      add_custom_command(
        OUTPUT ${work_dir}/${name} ${work_dir}/${name}.lines
        COMMAND ${CMAKE_COMMAND} -DMODE=validate -DSHADER_DIR=${ARG_SHADER_DIR} -DNAME=${name}
                -DWORK_DIR=${work_dir} -DVALIDATOR=${ARG_VALIDATOR} -P ${_TRAILRAY_EMBED_SHADERS_SCRIPT}
        DEPENDS ${stage_file} ${snippet_files} ${_TRAILRAY_EMBED_SHADERS_SCRIPT}
        COMMENT "Validating shader ${name} (glslangValidator)"
        VERBATIM)
      list(APPEND expanded_files ${work_dir}/${name} ${work_dir}/${name}.lines)
      list(APPEND names ${name})
    endforeach()
    set(output ${CMAKE_CURRENT_BINARY_DIR}/embedded_shaders.cpp)
    string(REPLACE ";" "," name_list "${names}")
    add_custom_command(
      OUTPUT ${output}
      COMMAND ${CMAKE_COMMAND} -DMODE=embed -DNAMES=${name_list} -DWORK_DIR=${work_dir} -DOUTPUT=${output}
              -P ${_TRAILRAY_EMBED_SHADERS_SCRIPT}
      DEPENDS ${expanded_files} ${_TRAILRAY_EMBED_SHADERS_SCRIPT}
      COMMENT "Embedding shaders into embedded_shaders.cpp"
      VERBATIM)
    set(${out_var} ${output} PARENT_SCOPE)
  endfunction()
  return()
endif()

# ---------------------------------------------------------------------------------------------
# Script mode.
cmake_minimum_required(VERSION 3.25)  # policies (IN_LIST) as in the project

# Appends the lines of SHADER_DIR/<name> to the variables `expanded` (text) and `segments`
# ("file|first line|line count" entries, in order), replacing include lines by the snippet.
function(_expand_file name depth)
  if(depth GREATER 16)
    message(FATAL_ERROR "${SHADER_DIR}/${name}: includes nested more than 16 deep")
  endif()
  set(path ${SHADER_DIR}/${name})
  file(READ ${path} content)
  string(REPLACE "\r\n" "\n" content "${content}")
  if(NOT content MATCHES "\n$")
    string(APPEND content "\n")
  endif()
  set(line_number 0)
  set(run_start 1)  # first line of the current run of this file's own lines
  set(run_length 0)
  while(NOT content STREQUAL "")
    string(FIND "${content}" "\n" newline)
    math(EXPR after "${newline} + 1")
    string(SUBSTRING "${content}" 0 ${after} line)
    string(SUBSTRING "${content}" ${after} -1 content)
    math(EXPR line_number "${line_number} + 1")
    if(line MATCHES "^[ \t]*#[ \t]*include[ \t]+\"([^\"]+)\"[ \t]*\n$")
      set(snippet ${CMAKE_MATCH_1})
      if(NOT EXISTS ${SHADER_DIR}/${snippet})
        message(FATAL_ERROR "${path}:${line_number}: cannot include \"${snippet}\": no such file in ${SHADER_DIR}")
      endif()
      if(run_length GREATER 0)
        list(APPEND segments "${name}|${run_start}|${run_length}")
      endif()
      math(EXPR run_start "${line_number} + 1")
      set(run_length 0)
      if(NOT snippet IN_LIST included)
        list(APPEND included ${snippet})
        math(EXPR next_depth "${depth} + 1")
        _expand_file(${snippet} ${next_depth})
      endif()
    else()
      if(line MATCHES "^[ \t]*#[ \t]*version" AND NOT depth EQUAL 0)
        message(FATAL_ERROR "${path}:${line_number}: an included snippet must not have a #version line")
      endif()
      string(APPEND expanded "${line}")
      math(EXPR run_length "${run_length} + 1")
    endif()
  endwhile()
  if(run_length GREATER 0)
    list(APPEND segments "${name}|${run_start}|${run_length}")
  endif()
  set(expanded "${expanded}" PARENT_SCOPE)
  set(segments "${segments}" PARENT_SCOPE)
  set(included "${included}" PARENT_SCOPE)
endfunction()

# Maps line `line` of the expanded source to "file:line" through `segments`.
function(_locate line out_var)
  set(first 1)
  foreach(segment ${segments})
    string(REPLACE "|" ";" fields "${segment}")
    list(GET fields 0 file)
    list(GET fields 1 file_first)
    list(GET fields 2 count)
    math(EXPR next "${first} + ${count}")
    if(line LESS next)
      math(EXPR file_line "${file_first} + ${line} - ${first}")
      set(${out_var} "${SHADER_DIR}/${file}:${file_line}" PARENT_SCOPE)
      return()
    endif()
    set(first ${next})
  endforeach()
  set(${out_var} "${SHADER_DIR}/${NAME}:${line} (expanded)" PARENT_SCOPE)
endfunction()

if(MODE STREQUAL "validate")
  set(expanded "")
  set(segments "")
  set(included "")
  _expand_file(${NAME} 0)
  set(output ${WORK_DIR}/${NAME})
  get_filename_component(dir ${output} DIRECTORY)
  file(MAKE_DIRECTORY ${dir})
  # The expanded copy keeps the name: glslangValidator tells the stage from the extension.
  file(WRITE ${output} "${expanded}")
  execute_process(COMMAND ${VALIDATOR} ${output} RESULT_VARIABLE status OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(NOT status EQUAL 0)
    # "ERROR: 0:12: 'x' : undeclared identifier" -> "src/render/shaders/a.frag:12: ERROR: ..."
    # Messages quote GLSL (';' : syntax error): hide semicolons from CMake's list splitting.
    string(REPLACE ";" "<semicolon>" log "${log}")
    string(REPLACE "\n" ";" log_lines "${log}")
    set(report "")
    foreach(log_line ${log_lines})
      string(FIND "${log_line}" "${output}" names_expanded_file)
      if(log_line MATCHES "^(ERROR|WARNING): [0-9]+:([0-9]+): (.*)$")
        set(kind ${CMAKE_MATCH_1})
        set(message_text "${CMAKE_MATCH_3}")
        _locate(${CMAKE_MATCH_2} where)
        string(APPEND report "${where}: ${kind}: ${message_text}\n")
      elseif(names_expanded_file EQUAL -1 AND NOT log_line STREQUAL "")
        string(APPEND report "${log_line}\n")
      endif()
    endforeach()
    string(REPLACE "<semicolon>" ";" report "${report}")
    # No output may survive a failure, or the next build would take the shader as checked.
    file(REMOVE ${output} ${output}.lines)
    # NOTICE prints the lines as they are (FATAL_ERROR would re-wrap them), one error a line.
    message(NOTICE "${report}")
    message(FATAL_ERROR "shader ${SHADER_DIR}/${NAME} does not compile (glslangValidator, GLSL ES 3.00)")
  endif()
  string(REPLACE ";" "\n" segment_lines "${segments}")
  file(WRITE ${WORK_DIR}/${NAME}.lines "${segment_lines}\n")
elseif(MODE STREQUAL "embed")
  string(REPLACE "," ";" names "${NAMES}")
  set(code "// Generated by cmake/EmbedShaders.cmake from src/render/shaders/: do not edit.\n")
  string(APPEND code "#include \"render/gl/shader_source.hpp\"\n\nnamespace trailray::render::detail {\nnamespace {\n\n")
  set(table "")
  set(index 0)
  foreach(name ${names})
    file(READ ${WORK_DIR}/${name} hex HEX)
    file(SIZE ${WORK_DIR}/${name} size)
    string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
    # Lines of 16 bytes keep the generated file readable in a diff or a debugger.
    string(REPEAT "0x..," 16 sixteen_bytes)  # CMake's regular expressions have no {n}
    string(REGEX REPLACE "(${sixteen_bytes})" "\\1\n    " bytes "${bytes}")
    string(APPEND code "// ${name}\nconstexpr unsigned char kText${index}[] = {\n    ${bytes}0x00};\n")
    file(STRINGS ${WORK_DIR}/${name}.lines segment_lines)
    string(APPEND code "constexpr EmbeddedLineSegment kLines${index}[] = {\n")
    set(first 1)
    foreach(segment ${segment_lines})
      string(REPLACE "|" ";" fields "${segment}")
      list(GET fields 0 file)
      list(GET fields 1 file_first)
      list(GET fields 2 count)
      string(APPEND code "    {${first}, ${count}, \"${file}\", ${file_first}},\n")
      math(EXPR first "${first} + ${count}")
    endforeach()
    string(APPEND code "};\n\n")
    string(APPEND table "    {\"${name}\", kText${index}, ${size}, kLines${index}, std::size(kLines${index})},\n")
    math(EXPR index "${index} + 1")
  endforeach()
  if(table STREQUAL "")  # no shaders yet: C++ has no empty arrays
    string(APPEND code "}  // namespace\n\nstd::span<const EmbeddedShaderFile> embedded_shader_files() { return {}; }\n\n")
  else()
    string(APPEND code "constexpr EmbeddedShaderFile kFiles[] = {\n${table}};\n\n}  // namespace\n\n")
    string(APPEND code "std::span<const EmbeddedShaderFile> embedded_shader_files() { return kFiles; }\n\n")
  endif()
  string(APPEND code "}  // namespace trailray::render::detail\n")
  # Rewritten only on change: Ninja then sees the file unchanged (restat) and compiles nothing
  # when the shaders were only touched (a checkout, a branch switch).
  set(previous "")
  if(EXISTS ${OUTPUT})
    file(READ ${OUTPUT} previous)
  endif()
  if(NOT previous STREQUAL code)
    file(WRITE ${OUTPUT} "${code}")
  endif()
else()
  message(FATAL_ERROR "EmbedShaders.cmake: MODE must be validate or embed, not '${MODE}'")
endif()
