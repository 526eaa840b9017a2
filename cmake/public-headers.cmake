# The installed headers: what a consumer of the library needs, and nothing else. The public entry
# points are the headers the Python package includes (python/src/, the broadest consumer in this
# tree), the installed-tree example (examples/consumer/) and the few entry points the CLI uses that
# neither does; they are installed with every header they include, so the installed tree compiles on
# its own. The rest (readers' internals, the AD kernels' .hxx bodies, the CLI) stays private.
set(WHIRL_PUBLIC_ENTRY_HEADERS
  # model sources: YAML cases, OpenFAST decks
  src/io/case/case_file.hpp src/turbine/load_model.hpp src/turbine/elastodyn_model.hpp
  src/io/openfast/openfast_deck.hpp src/model/model.hpp src/model/operating_condition.hpp
  # operating points, linear models, trims, time simulation, controller design
  linearize/operating_point.hpp linearize/linearize.hpp linearize/periodic.hpp linearize/sweep.hpp
  linearize/trim.hpp linearize/state_space.hpp linearize/mbc.hpp linearize/simulate.hpp
  linearize/closed_loop.hpp linearize/frequency_response.hpp linearize/loop_margins.hpp
  linearize/export_point.hpp linearize/export_sweep.hpp linearize/point_validity.hpp
  # modes, Campbell diagrams, Floquet, .lin files
  modal/modes.hpp modal/eigen.hpp modal/rotor_modes.hpp modal/tracking.hpp modal/campbell_sweep.hpp
  modal/floquet.hpp modal/lin_modes.hpp
  # result files
  src/writers/output_set.hpp src/writers/campbell_output.hpp)

# `out` = the headers `entries` include, directly or through each other ("…" includes of repository
# files), the entries with them.
function(whirl_header_closure out)
  set(seen "")
  set(todo ${ARGN})
  while(todo)
    list(POP_FRONT todo h)
    if(h IN_LIST seen)
      continue()
    endif()
    if(NOT EXISTS ${PROJECT_SOURCE_DIR}/${h})
      message(FATAL_ERROR "public header ${h} does not exist (cmake/public-headers.cmake)")
    endif()
    list(APPEND seen ${h})
    file(STRINGS ${PROJECT_SOURCE_DIR}/${h} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    foreach(l IN LISTS lines)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" inc "${l}")
      if(EXISTS ${PROJECT_SOURCE_DIR}/${inc})
        list(APPEND todo ${inc})
      endif()
    endforeach()
  endwhile()
  set(${out} ${seen} PARENT_SCOPE)
endfunction()

# Installs the closure of the entry headers under include/whirl/<repository path>.
function(whirl_install_public_headers)
  # What the Python package includes of the library is public by definition.
  file(GLOB python_sources ${PROJECT_SOURCE_DIR}/python/src/*.cpp ${PROJECT_SOURCE_DIR}/python/src/*.hpp)
  set(python_entries "")
  foreach(f IN LISTS python_sources)
    file(STRINGS ${f} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    foreach(l IN LISTS lines)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" inc "${l}")
      if(NOT inc MATCHES "^python/" AND EXISTS ${PROJECT_SOURCE_DIR}/${inc})
        list(APPEND python_entries ${inc})
      endif()
    endforeach()
  endforeach()
  whirl_header_closure(headers ${WHIRL_PUBLIC_ENTRY_HEADERS} ${python_entries} ${ARGN})
  foreach(h IN LISTS headers)
    get_filename_component(dir ${h} DIRECTORY)
    install(FILES ${PROJECT_SOURCE_DIR}/${h} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/whirl/${dir})
  endforeach()
  # Any header added to the closure later is picked up at the next configure.
  foreach(h IN LISTS headers)
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${h})
  endforeach()
  list(LENGTH headers n)
  message(STATUS "whirl: ${n} public headers installed (cmake/public-headers.cmake)")
endfunction()
