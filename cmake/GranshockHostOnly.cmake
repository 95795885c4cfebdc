# toml++ does not compile as CUDA: nvcc's front end rewrites the generic lambdas of its
# table::for_each into code g++ rejects ("'__T0' was not declared in this scope"). No
# source that reads TOML holds a kernel, so in a CUDA build (nvcc_wrapper as the C++
# compiler) such a source is compiled by the host compiler alone (nvcc --host-only;
# docs/cuda.md). granshock_host_only_toml_sources(target) finds them itself, following
# the repository's own includes, so that a new TOML reader cannot break the CUDA build
# (io/dump_map.cpp once did: a hand-kept list had missed it).

# Whether FILE includes toml++, directly or through the repository's headers. The result
# of each header is cached in a global property for the rest of the configure run.
function(_granshock_includes_toml file out)
  get_property(known GLOBAL PROPERTY "granshock_toml_${file}" SET)
  if(known)
    get_property(result GLOBAL PROPERTY "granshock_toml_${file}")
    set(${out} ${result} PARENT_SCOPE)
    return()
  endif()
  set_property(GLOBAL PROPERTY "granshock_toml_${file}" FALSE)  # cycles end here
  file(STRINGS "${file}" lines REGEX "^[ \t]*#[ \t]*include")
  set(result FALSE)
  get_filename_component(dir "${file}" DIRECTORY)
  foreach(line IN LISTS lines)
    if(line MATCHES "toml\\+\\+/")
      set(result TRUE)
      break()
    endif()
    if(NOT line MATCHES "#[ \t]*include[ \t]*\"([^\"]+)\"")
      continue()
    endif()
    set(name "${CMAKE_MATCH_1}")
    foreach(base IN ITEMS "${dir}" "${PROJECT_SOURCE_DIR}" "${PROJECT_SOURCE_DIR}/kernels"
                          "${PROJECT_SOURCE_DIR}/core")
      if(EXISTS "${base}/${name}" AND NOT IS_DIRECTORY "${base}/${name}")
        _granshock_includes_toml("${base}/${name}" included)
        if(included)
          set(result TRUE)
        endif()
        break()
      endif()
    endforeach()
    if(result)
      break()
    endif()
  endforeach()
  set_property(GLOBAL PROPERTY "granshock_toml_${file}" ${result})
  set(${out} ${result} PARENT_SCOPE)
endfunction()

# Called in the directory that defines the target (source properties are per directory).
function(granshock_host_only_toml_sources target)
  if(NOT GRANSHOCK_NVCC)
    return()
  endif()
  get_target_property(sources ${target} SOURCES)
  get_target_property(source_dir ${target} SOURCE_DIR)
  set(host_only)
  foreach(source IN LISTS sources)
    if(NOT source MATCHES "\\.cpp$")
      continue()
    endif()
    if(NOT IS_ABSOLUTE "${source}")
      set(source "${source_dir}/${source}")
    endif()
    # A source generated at build time (generated/build_stamp.cpp) does not exist yet
    # when a fresh build is configured; the generators write no TOML reader.
    if(NOT EXISTS "${source}")
      continue()
    endif()
    _granshock_includes_toml("${source}" toml)
    if(toml)
      list(APPEND host_only "${source}")
    endif()
  endforeach()
  if(host_only)
    set_source_files_properties(${host_only} PROPERTIES COMPILE_OPTIONS "--host-only")
  endif()
endfunction()
