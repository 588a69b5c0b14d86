# The layers of docs/architecture.md, enforced when the build is configured: every project
# target links only targets of its own layer or below, or the configuration stops naming
# both. Idea: the folders are the layers (1 sw/host, 2 rtl and sc_model, 3 sw/tools,
# 4 sw/cli, 5 bench, 6 tests), so the check needs no list of targets: a new target is
# checked by where it lives. Included by the root CMakeLists.txt after every folder is
# added; tests/cmake/layer_violation is a small project that breaks the rule on purpose.

# The layer folders, lowest first: a folder's layer is its position in this list (1 to 6).
set(ncinterp_layer_folders "sw/host" "rtl|sc_model" "sw/tools" "sw/cli" "bench" "tests")

function(ncinterp_layer_of dir out)
  file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${dir})
  set(layer 0)
  foreach(folders IN LISTS ncinterp_layer_folders)
    math(EXPR layer "${layer} + 1")
    if(rel MATCHES "^(${folders})(/|$)")
      set(${out} ${layer} PARENT_SCOPE)
      return()
    endif()
  endforeach()
  message(FATAL_ERROR "${rel}: a target outside the layer folders (docs/architecture.md)")
endfunction()

# Every project target against every project target it links: a link to a higher layer
# (a library reaching up, or a benchmark linking a test library) stops the configuration.
function(ncinterp_check_layers_in dir)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(NOT type MATCHES "LIBRARY|EXECUTABLE")
      continue()
    endif()
    ncinterp_layer_of(${dir} layer)
    get_target_property(links ${target} LINK_LIBRARIES)
    get_target_property(interface_links ${target} INTERFACE_LINK_LIBRARIES)
    foreach(dep IN LISTS links interface_links)
      if(NOT TARGET ${dep})
        continue()
      endif()
      get_target_property(imported ${dep} IMPORTED)
      get_target_property(alias ${dep} ALIASED_TARGET)
      if(imported OR alias)
        continue()
      endif()
      get_target_property(dep_dir ${dep} SOURCE_DIR)
      ncinterp_layer_of(${dep_dir} dep_layer)
      if(dep_layer GREATER layer)
        file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${dir})
        file(RELATIVE_PATH dep_rel ${PROJECT_SOURCE_DIR} ${dep_dir})
        message(FATAL_ERROR "${target} (${rel}, layer ${layer}) links ${dep} (${dep_rel}, "
                            "layer ${dep_layer}): a target links only its layer or below")
      endif()
    endforeach()
  endforeach()
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    ncinterp_check_layers_in(${sub})
  endforeach()
endfunction()
