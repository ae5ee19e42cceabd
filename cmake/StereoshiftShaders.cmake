# StereoshiftShaders.cmake: converts shaders to stereo as build steps.
#
#   stereoshift_add_shaders(<target>
#     SOURCES <shader>...            | MANIFEST <scene.toml>
#     OUTPUT_DIR <dir>
#     [BASE_DIR <dir>]                 (default: CMAKE_CURRENT_SOURCE_DIR)
#     [INCLUDE_DIRS <dir>...]          (-I)
#     [DEFINES <NAME[=VALUE]>...]      (-D)
#     [TARGET_LANGUAGE glsl|essl|hlsl|msl|spirv|spirv-asm]
#     [LANGUAGE glsl|hlsl]             (-x: the input language, whatever the file names say)
#     [TARGET_ENV vulkan1.0|vulkan1.1|vulkan1.2|vulkan1.3|opengl|opengl4.5]   (--target-env)
#     [TARGET_SPV spv1.0 ... spv1.6]   (--target-spv)
#     [STAGE_EXTENSIONS <ext>=<stage>...]   (--stage-ext: vp=vert fp=frag)
#     [OPTIONS <stereoshift option>...]
#     [PER_PIPELINE]                   (one build step per pipeline instead of one for the target)
#     [NO_SERVICE]                     (PER_PIPELINE: convert each pipeline in its own process)
#     [OUTPUTS_VAR <variable>])
#
# SOURCES: stages that share a directory and the name without the stage part (lit.vert + lit.frag,
# water.vert.hlsl + water.frag.hlsl, 5.1.x.vs + 5.1.x.fs, basicVS.hlsl + basicPS.hlsl) form one
# pipeline, because only the pipeline's last pre-rasterization stage is shifted and the eye-parameter
# binding is chosen for the whole pipeline; a lone shader is a pipeline of one. Each output keeps its
# source's file name and its path relative to BASE_DIR, under OUTPUT_DIR.
#
# By default the target is one build step: `stereoshift build BASE_DIR --files-from <list>` over
# the SOURCES (a generated list), incremental inside by its content-hash cache in OUTPUT_DIR, with
# one depfile of every input and #included file it read. Its declared output is
# OUTPUT_DIR/stereoshift-report.json; the shaders are its byproducts, which Ninja re-stats: an
# output `build` did not rewrite (its bytes are the same) leaves whatever depends on it alone. A
# clean build then costs what `stereoshift build` costs (one process, parallel workers), an edit
# one pipeline's conversion.
#
# PER_PIPELINE: one `stereoshift --pipeline` command per pipeline, each with its own depfile (the
# stages and every #included file), so an edit to a header reruns exactly the commands of the
# pipelines that include it. These commands go through stereoshift's conversion service (`--service`): a per-user
# server that keeps glslang initialised, started by the first command and shared by every Ninja or
# make job, so each command costs milliseconds instead of glslang's ~0.1 s set-up. Its outputs are
# byte for byte the in-process ones, and a command whose server cannot be reached converts
# in-process. NO_SERVICE, or -DSTEREOSHIFT_USE_SERVICE=OFF for the whole project, turns it off.
#
# MANIFEST: one `stereoshift build <manifest>` command (incremental on its own, with a content-hash
# cache in OUTPUT_DIR) whose declared output is OUTPUT_DIR/stereoshift-report.json.
#
# <target> is an ALL custom target that depends on the outputs. The absolute output paths are in
# <target>'s STEREOSHIFT_OUTPUTS property and, with OUTPUTS_VAR, in that variable of the caller;
# STEREOSHIFT_OUTPUT_DIR holds the absolute OUTPUT_DIR. Relative paths: SOURCES, BASE_DIR,
# INCLUDE_DIRS and MANIFEST against CMAKE_CURRENT_SOURCE_DIR, OUTPUT_DIR against
# CMAKE_CURRENT_BINARY_DIR (as add_custom_command's OUTPUT).

# DEPFILE with the Makefile generators and cmake_path() need 3.20.
if(CMAKE_VERSION VERSION_LESS 3.20)
  message(FATAL_ERROR "stereoshift_add_shaders needs CMake 3.20 or newer (this is ${CMAKE_VERSION})")
endif()
include_guard(GLOBAL)

# CMP0116 NEW: the Ninja generators pass each depfile through `cmake -E cmake_transform_depfile`,
# which rewrites its paths to the ones build.ninja uses. Under OLD, Ninja reads the depfile as it is:
# stereoshift's absolute target paths ("/build/stereo/lit.vert") then never match the relative output
# names ("stereo/lit.vert"), and Ninja reruns every step on every build. A function runs with the
# policy settings of the place it is defined, so setting NEW here holds whatever the caller's
# cmake_minimum_required() says (the Makefile generators read absolute paths alike either way).
cmake_policy(PUSH)
cmake_policy(SET CMP0116 NEW)

option(STEREOSHIFT_USE_SERVICE "stereoshift_add_shaders: convert SOURCES through stereoshift's warm conversion service" ON)

function(stereoshift_add_shaders target)
  # (Inside the function: the module is included once, and variables would not reach other directories.)
  set(target_languages glsl essl hlsl msl spirv spirv-asm)
  # Options the function decides itself: a caller's copy would name other outputs than the declared ones.
  set(reserved_options -o --output --depfile --pipeline --report)
  cmake_parse_arguments(PARSE_ARGV 1 arg
    "NO_SERVICE;PER_PIPELINE"
    "OUTPUT_DIR;BASE_DIR;MANIFEST;TARGET_LANGUAGE;LANGUAGE;TARGET_ENV;TARGET_SPV;OUTPUTS_VAR"
    "SOURCES;INCLUDE_DIRS;DEFINES;OPTIONS;STAGE_EXTENSIONS")

  # --- argument checks --------------------------------------------------------------------------
  set(usage "stereoshift_add_shaders(<target> SOURCES <shader>... | MANIFEST <file> OUTPUT_DIR <dir> ...)")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "stereoshift_add_shaders(${target}): unknown arguments: ${arg_UNPARSED_ARGUMENTS}\n  usage: ${usage}")
  endif()
  # An empty list after a multi-value keyword (DEFINES ${none}) is fine; a one-value keyword needs its value.
  foreach(keyword IN LISTS arg_KEYWORDS_MISSING_VALUES)
    if(keyword MATCHES "^(OUTPUT_DIR|BASE_DIR|MANIFEST|TARGET_LANGUAGE|LANGUAGE|TARGET_ENV|TARGET_SPV|OUTPUTS_VAR)$")
      message(FATAL_ERROR "stereoshift_add_shaders(${target}): ${keyword} needs a value")
    endif()
  endforeach()
  if(TARGET "${target}")
    message(FATAL_ERROR "stereoshift_add_shaders(${target}): a target named '${target}' already exists")
  endif()
  if(NOT TARGET stereoshift::stereoshift)
    message(FATAL_ERROR "stereoshift_add_shaders(${target}): the stereoshift::stereoshift executable target is not defined; call find_package(stereoshift REQUIRED) first")
  endif()
  if(NOT DEFINED arg_OUTPUT_DIR)
    message(FATAL_ERROR "stereoshift_add_shaders(${target}): OUTPUT_DIR is required\n  usage: ${usage}")
  endif()
  if(arg_SOURCES AND DEFINED arg_MANIFEST)
    message(FATAL_ERROR "stereoshift_add_shaders(${target}): give SOURCES or MANIFEST, not both (a manifest lists its own shaders)")
  endif()
  if(DEFINED arg_MANIFEST AND DEFINED arg_BASE_DIR)
    message(FATAL_ERROR "stereoshift_add_shaders(${target}): BASE_DIR applies to SOURCES only (a manifest's `source` sets its root)")
  endif()
  if(NOT arg_SOURCES AND NOT DEFINED arg_MANIFEST)
    message(FATAL_ERROR "stereoshift_add_shaders(${target}): no shaders: give SOURCES <shader>... or MANIFEST <file>\n  usage: ${usage}")
  endif()
  if(DEFINED arg_TARGET_LANGUAGE AND NOT arg_TARGET_LANGUAGE IN_LIST target_languages)
    message(FATAL_ERROR "stereoshift_add_shaders(${target}): TARGET_LANGUAGE '${arg_TARGET_LANGUAGE}' is not one of: ${target_languages}")
  endif()
  if(DEFINED arg_LANGUAGE AND NOT arg_LANGUAGE MATCHES "^(glsl|hlsl)$")
    message(FATAL_ERROR "stereoshift_add_shaders(${target}): LANGUAGE '${arg_LANGUAGE}' is not one of: glsl hlsl")
  endif()
  if(DEFINED arg_TARGET_ENV AND NOT arg_TARGET_ENV MATCHES "^(vulkan1\\.[0-3]|opengl|opengl4\\.5)$")
    message(FATAL_ERROR "stereoshift_add_shaders(${target}): TARGET_ENV '${arg_TARGET_ENV}' is not one of: vulkan1.0 vulkan1.1 vulkan1.2 vulkan1.3 opengl opengl4.5")
  endif()
  if(DEFINED arg_TARGET_SPV AND NOT arg_TARGET_SPV MATCHES "^spv1\\.[0-6]$")
    message(FATAL_ERROR "stereoshift_add_shaders(${target}): TARGET_SPV '${arg_TARGET_SPV}' is not one of: spv1.0 ... spv1.6")
  endif()
  set(extra_stage_extensions "")
  foreach(mapping IN LISTS arg_STAGE_EXTENSIONS)
    if(NOT mapping MATCHES "^\\.?([A-Za-z0-9_]+)=(vert|tesc|tese|geom|frag|comp|mesh|task)$")
      message(FATAL_ERROR "stereoshift_add_shaders(${target}): STAGE_EXTENSIONS '${mapping}' is not <ext>=<stage> (vert tesc tese geom frag comp mesh task)")
    endif()
    string(TOLOWER "${CMAKE_MATCH_1}" extension)
    list(APPEND extra_stage_extensions "${extension}")
  endforeach()
  foreach(option IN LISTS arg_OPTIONS)
    string(REGEX REPLACE "=.*" "" option_name "${option}")
    if(option_name IN_LIST reserved_options)
      message(FATAL_ERROR "stereoshift_add_shaders(${target}): OPTIONS may not contain '${option_name}': the function sets the outputs, depfiles and pipelines itself")
    endif()
  endforeach()

  cmake_path(ABSOLUTE_PATH arg_OUTPUT_DIR BASE_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}" NORMALIZE OUTPUT_VARIABLE output_dir)
  string(REGEX REPLACE "(.)/+$" "\\1" output_dir "${output_dir}")  # "out/" -> "out": outputs are "out/x"
  # A build step owns its OUTPUT_DIR (its cache, its report, the removal of outputs whose source
  # went): two targets there would undo each other's work.
  get_property(owned_dirs GLOBAL PROPERTY STEREOSHIFT_OUTPUT_DIRS)
  if(output_dir IN_LIST owned_dirs AND (DEFINED arg_MANIFEST OR NOT arg_PER_PIPELINE))
    message(FATAL_ERROR "stereoshift_add_shaders(${target}): OUTPUT_DIR '${output_dir}' is already another target's; give each target its own")
  endif()
  set_property(GLOBAL APPEND PROPERTY STEREOSHIFT_OUTPUT_DIRS "${output_dir}")

  # --- the conversion options every command shares ----------------------------------------------
  set(conversion_args "")
  foreach(dir IN LISTS arg_INCLUDE_DIRS)
    cmake_path(ABSOLUTE_PATH dir BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE OUTPUT_VARIABLE dir)
    list(APPEND conversion_args "-I" "${dir}")
  endforeach()
  foreach(definition IN LISTS arg_DEFINES)
    string(REGEX REPLACE "^-D" "" definition "${definition}")
    list(APPEND conversion_args "-D${definition}")
  endforeach()
  if(DEFINED arg_TARGET_LANGUAGE)
    list(APPEND conversion_args "--target" "${arg_TARGET_LANGUAGE}")
  endif()
  if(DEFINED arg_LANGUAGE)
    list(APPEND conversion_args "-x" "${arg_LANGUAGE}")
  endif()
  if(DEFINED arg_TARGET_ENV)
    list(APPEND conversion_args "--target-env" "${arg_TARGET_ENV}")
  endif()
  if(DEFINED arg_TARGET_SPV)
    list(APPEND conversion_args "--target-spv" "${arg_TARGET_SPV}")
  endif()
  foreach(mapping IN LISTS arg_STAGE_EXTENSIONS)
    list(APPEND conversion_args "--stage-ext" "${mapping}")
  endforeach()
  list(APPEND conversion_args ${arg_OPTIONS})

  # Only the per-pipeline commands: `build` (MANIFEST) warms its own workers. A caller's own
  # --service / --no-service in OPTIONS is left to decide.
  set(service_args "")
  if(STEREOSHIFT_USE_SERVICE AND NOT arg_NO_SERVICE AND NOT "--no-service" IN_LIST arg_OPTIONS
     AND NOT "--service" IN_LIST arg_OPTIONS)
    set(service_args "--service")
  endif()

  set(depfile_dir "${CMAKE_CURRENT_BINARY_DIR}/stereoshift_deps/${target}")
  set(all_outputs "")
  set(step_outputs "")

  if(DEFINED arg_MANIFEST)
    # --- MANIFEST: one incremental `stereoshift build`; the report stands for all its outputs -----
    cmake_path(ABSOLUTE_PATH arg_MANIFEST BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE OUTPUT_VARIABLE manifest)
    if(NOT EXISTS "${manifest}" OR IS_DIRECTORY "${manifest}")
      message(FATAL_ERROR "stereoshift_add_shaders(${target}): MANIFEST '${manifest}' is not a file")
    endif()
    set(report "${output_dir}/stereoshift-report.json")
    set(depfile "${depfile_dir}/stereoshift-report.json.d")
    add_custom_command(
      OUTPUT "${report}"
      COMMAND stereoshift::stereoshift build ${conversion_args} "${manifest}" -o "${output_dir}" --depfile "${depfile}"
      # Whether `build` rewrites a report whose content did not change is its own business; the
      # touch keeps the declared output newer than the inputs that triggered this run, else make
      # and Ninja would rerun the step on every build.
      COMMAND "${CMAKE_COMMAND}" -E touch "${report}"
      DEPENDS "${manifest}" stereoshift::stereoshift
      DEPFILE "${depfile}"
      COMMENT "stereoshift: ${target}: converting the shaders of ${arg_MANIFEST}"
      VERBATIM)
    list(APPEND all_outputs "${report}")
  else()
    # --- SOURCES: group the stages into pipelines -------------------------------------------------
    if(DEFINED arg_BASE_DIR)
      cmake_path(ABSOLUTE_PATH arg_BASE_DIR BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE OUTPUT_VARIABLE base_dir)
    else()
      set(base_dir "${CMAKE_CURRENT_SOURCE_DIR}")
    endif()
    set(sources "")
    foreach(source IN LISTS arg_SOURCES)
      cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE OUTPUT_VARIABLE source)
      get_source_file_property(generated "${source}" GENERATED)
      if(NOT EXISTS "${source}" AND NOT generated)
        message(FATAL_ERROR "stereoshift_add_shaders(${target}): source '${source}' does not exist")
      endif()
      cmake_path(IS_PREFIX base_dir "${source}" NORMALIZE inside_base_dir)
      if(NOT inside_base_dir)
        message(FATAL_ERROR "stereoshift_add_shaders(${target}): source '${source}' is not inside BASE_DIR '${base_dir}'; outputs mirror the sources' paths relative to BASE_DIR")
      endif()
      if(source MATCHES ",")
        message(FATAL_ERROR "stereoshift_add_shaders(${target}): source '${source}' contains a comma, which `stereoshift --pipeline` uses as its separator")
      endif()
      list(APPEND sources "${source}")
    endforeach()
    list(REMOVE_DUPLICATES sources)
    # Sorted, so the command lines do not depend on the order the caller listed the stages in.
    list(SORT sources)

    # The pipeline key is the CLI's (transpiler/source/stage_rules.cpp readStagedName): the directory plus the file
    # name without its language extension and its stage part (a stage extension, else a stage word
    # at the end or the start of an HLSL/GLSL/FX name: basicVS, water_ps, VS_Sky).
    set(stage_tokens "vert|vertex|vs|tesc|tesscontrol|tcs|hs|hull|tese|tesseval|tessevaluation|tes|ds|domain|geom|geometry|gs|frag|fragment|fs|ps|pixel|comp|compute|cs|mesh|ms|task|as|amplification")
    set(stage_words "vs|vert|vertex|ps|frag|fragment|pixel|gs|geom|hs|tesc|ds|tese|cs|comp")
    set(pipeline_keys "")
    set(key_of "")
    foreach(source IN LISTS sources)
      get_filename_component(source_dir "${source}" DIRECTORY)
      get_filename_component(name "${source}" NAME)
      string(TOLOWER "${name}" lower)
      set(has_language_extension FALSE)
      if(lower MATCHES "^(.+)\\.(glsl|hlsl|fx|spv)$")
        string(LENGTH "${CMAKE_MATCH_1}" stem_length)
        string(SUBSTRING "${name}" 0 ${stem_length} name)
        string(TOLOWER "${name}" lower)
        set(has_language_extension TRUE)
      endif()
      set(staged FALSE)
      if(lower MATCHES "^(.+)\\.([a-z0-9_]+)$")
        set(stem_lower "${CMAKE_MATCH_1}")
        set(extension "${CMAKE_MATCH_2}")
        if(extension IN_LIST extra_stage_extensions OR extension MATCHES "^(${stage_tokens})(shader)?$"
           OR extension MATCHES "^(vert|vertex|vs|tesc|tcs|hs|tese|tes|ds|geom|gs|frag|fs|ps|comp|cs)h$")
          string(LENGTH "${stem_lower}" stem_length)
          string(SUBSTRING "${name}" 0 ${stem_length} name)
          set(staged TRUE)
        endif()
      endif()
      if(NOT staged AND has_language_extension)
        string(TOLOWER "${name}" lower)
        if(name MATCHES "^(.*[a-z0-9])(VS|PS|GS|HS|DS|CS|Vert|Frag|Geom|Tesc|Tese|Comp|Vertex|Fragment|Pixel)$")
          set(name "${CMAKE_MATCH_1}")
        elseif(lower MATCHES "^(.+)[._ -](${stage_words})$")
          string(LENGTH "${CMAKE_MATCH_1}" stem_length)
          string(SUBSTRING "${name}" 0 ${stem_length} name)
        elseif(lower MATCHES "^(${stage_words})[._ -](.+)$")
          string(LENGTH "${CMAKE_MATCH_1}" word_length)
          math(EXPR word_length "${word_length} + 1")
          string(SUBSTRING "${name}" ${word_length} -1 name)
        endif()
      endif()
      list(APPEND pipeline_keys "${source_dir}/${name}")
      list(APPEND key_of "${source_dir}/${name}")
    endforeach()
    list(REMOVE_DUPLICATES pipeline_keys)

    foreach(key IN LISTS pipeline_keys)
      set(stages "")
      set(stage_names "")
      set(index 0)
      foreach(source IN LISTS sources)
        list(GET key_of ${index} source_key)
        math(EXPR index "${index} + 1")
        if(source_key STREQUAL key)
          list(APPEND stages "${source}")
          get_filename_component(extensions "${source}" EXT)
          string(REGEX REPLACE "^\\.([^.]*).*" "\\1" stage_name "${extensions}")
          list(APPEND stage_names "${stage_name}")
        endif()
      endforeach()

      file(RELATIVE_PATH relative_key "${base_dir}" "${key}")
      get_filename_component(source_dir "${key}" DIRECTORY)
      file(RELATIVE_PATH relative_dir "${base_dir}" "${source_dir}")
      if(relative_dir STREQUAL "")
        set(stage_output_dir "${output_dir}")
      else()
        set(stage_output_dir "${output_dir}/${relative_dir}")
      endif()
      set(outputs "")
      foreach(stage IN LISTS stages)
        get_filename_component(file_name "${stage}" NAME)
        list(APPEND outputs "${stage_output_dir}/${file_name}")
      endforeach()
      set(depfile "${depfile_dir}/${relative_key}.d")

      list(APPEND all_outputs ${outputs})
      if(NOT arg_PER_PIPELINE)
        continue()  # the one build step below converts them all
      endif()
      list(LENGTH stages stage_count)
      if(stage_count EQUAL 1)
        # A single shader names its output itself, whatever file name the CLI would pick for it.
        set(io_args "${stages}" -o "${outputs}")
      else()
        list(JOIN stages "," stage_list)
        set(io_args --pipeline "${stage_list}" -o "${stage_output_dir}")
      endif()
      list(JOIN stage_names ", " stage_names)
      add_custom_command(
        OUTPUT ${outputs}
        COMMAND stereoshift::stereoshift ${service_args} ${conversion_args} ${io_args} --depfile "${depfile}"
        DEPENDS ${stages} stereoshift::stereoshift
        DEPFILE "${depfile}"
        COMMENT "stereoshift: ${target}: ${relative_key} (${stage_names})"
        VERBATIM)
    endforeach()

    if(NOT arg_PER_PIPELINE)
      # --- one build step: `stereoshift build` over the listed sources -----------------------------
      set(listed "")
      foreach(source IN LISTS sources)
        file(RELATIVE_PATH relative_source "${base_dir}" "${source}")
        string(APPEND listed "${relative_source}\n")
      endforeach()
      # Written when generating, and only when the list changed: adding a source reruns the step.
      set(files_list "${depfile_dir}/sources.txt")
      file(GENERATE OUTPUT "${files_list}" CONTENT "${listed}")
      # `build` has its own workers: the conversion service's options are the per-pipeline commands'.
      set(build_args ${conversion_args})
      list(REMOVE_ITEM build_args --service --no-service)
      set(report "${output_dir}/stereoshift-report.json")
      set(depfile "${depfile_dir}/stereoshift-report.json.d")
      list(LENGTH sources source_count)
      list(LENGTH pipeline_keys pipeline_count)
      add_custom_command(
        OUTPUT "${report}"
        BYPRODUCTS ${all_outputs}
        COMMAND stereoshift::stereoshift build ${build_args} "${base_dir}" -o "${output_dir}" --files-from "${files_list}"
                --depfile "${depfile}" -q
        # The report stands for the step: touched, so it is newer than what triggered the run even
        # when `build` found it unchanged (the shaders themselves keep their times when unchanged).
        COMMAND "${CMAKE_COMMAND}" -E touch "${report}"
        DEPENDS ${sources} "${files_list}" stereoshift::stereoshift
        DEPFILE "${depfile}"
        COMMENT "stereoshift: ${target}: ${source_count} shaders in ${pipeline_count} pipelines (one build step)"
        VERBATIM)
      set(step_outputs "${report}")  # what the target waits for; OUTPUTS_VAR lists the shaders
    endif()
  endif()

  # One build step: the target waits for the step's report. Its shaders are byproducts, which
  # Ninja knows as the step's outputs; Make has no rule for them (depend on the target there).
  if(step_outputs)
    add_custom_target("${target}" ALL DEPENDS ${step_outputs})
  else()
    add_custom_target("${target}" ALL DEPENDS ${all_outputs})
  endif()
  set_target_properties("${target}" PROPERTIES
    STEREOSHIFT_OUTPUTS "${all_outputs}"
    STEREOSHIFT_OUTPUT_DIR "${output_dir}")
  if(DEFINED arg_OUTPUTS_VAR)
    set(${arg_OUTPUTS_VAR} "${all_outputs}" PARENT_SCOPE)
  endif()
endfunction()

cmake_policy(POP)
