# CTest `install_consumer_linearizes`: install the build BUILD into WORK/stage, configure and build the
# consumer project SOURCE against it (find_package(whirl), nothing else on the prefix path), run it
# on CASE and check the tower fore-aft frequency it prints (0.3272 Hz, [BranlardGeisler2022, §4.4],
# cases/landbased_2dof/reference.csv, 4 decimals as printed there).
file(REMOVE_RECURSE ${WORK})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${WORK}/stage
  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "install failed: ${err}")
endif()
# Only the public headers are installed (cmake/public-headers.cmake): the readers' internals and the
# CLI stay private.
foreach(private src/io/case/case_reader.hpp src/dynamics/residual.hxx src/cli/common.hpp
                linearize/ida_vector.hpp)
  if(EXISTS ${WORK}/stage/include/whirl/${private})
    message(FATAL_ERROR "a private header was installed: include/whirl/${private}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${WORK}/build -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${WORK}/stage
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "configure against the installed whirl failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK}/build RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "build against the installed whirl failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${WORK}/build/whirl_consumer ${CASE} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(rc)
  message(FATAL_ERROR "whirl_consumer failed (${rc}): ${err}")
endif()
if(NOT out MATCHES "tower FA 1: 0\\.3272 Hz")
  message(FATAL_ERROR "expected 'tower FA 1: 0.3272 Hz' in the output")
endif()

# The same program built by pkg-config alone (whirl.pc), as a Makefile or Meson user would.
set(ENV{PKG_CONFIG_PATH} "${WORK}/stage/lib/pkgconfig:$ENV{PKG_CONFIG_PATH}")
execute_process(COMMAND pkg-config --cflags --libs whirl RESULT_VARIABLE rc OUTPUT_VARIABLE flags
  ERROR_VARIABLE err OUTPUT_STRIP_TRAILING_WHITESPACE)
if(rc)
  message(FATAL_ERROR "pkg-config whirl failed: ${err}")
endif()
separate_arguments(flags UNIX_COMMAND "${flags}")
execute_process(COMMAND ${CXX} -O2 ${SOURCE}/main.cpp ${flags} -o ${WORK}/whirl_consumer_pc
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "build with pkg-config flags failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${WORK}/whirl_consumer_pc ${CASE} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc OR NOT out MATCHES "tower FA 1: 0\\.3272 Hz")
  message(FATAL_ERROR "the pkg-config build printed '${out}' (${rc}): ${err}")
endif()
