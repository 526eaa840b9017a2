# `whirl export --schedule` on one process and on 2 MPI ranks: every output file must be
# byte-identical. The whole file is compared, .mat included: whirl gives matio its own header text
# (Mat_CreateVer), so the 116-byte header carries no creation time, and every byte after it is data.
# With EXPECT_ERROR (a schedule whose point 2, rank 1's, fails): both runs fail with the same one
# `whirl: error:` line (mpirun adds its own banner) and write nothing.
# Variables: WHIRL (executable), MPIEXEC, CASE, SCHEDULE, AZIMUTHS, FORMAT (mat, lin or json),
# NFILES (files expected), OUT (scratch folder), EXPECT_ERROR (optional: text the error contains).
file(REMOVE_RECURSE ${OUT})
set(args export ${CASE} --schedule ${SCHEDULE} --azimuths ${AZIMUTHS} --format ${FORMAT})
if(EXPECT_ERROR)
  execute_process(COMMAND ${WHIRL} ${args} --out ${OUT}/one RESULT_VARIABLE rc1 ERROR_VARIABLE e1)
  execute_process(COMMAND ${MPIEXEC} -n 2 --oversubscribe ${WHIRL} ${args} --out ${OUT}/two
    RESULT_VARIABLE rc2 ERROR_VARIABLE e2)
  string(REGEX MATCHALL "whirl: error:[^\n]*" l1 "${e1}")
  string(REGEX MATCHALL "whirl: error:[^\n]*" l2 "${e2}")
  list(LENGTH l2 n2)
  if(rc1 EQUAL 0 OR rc2 EQUAL 0 OR NOT n2 EQUAL 1 OR NOT l1 STREQUAL l2 OR NOT l1 MATCHES "${EXPECT_ERROR}")
    message(FATAL_ERROR "expected one `whirl: error: …${EXPECT_ERROR}…` line and exit != 0 from both runs;\n"
      "one process (${rc1}): ${e1}\n2 ranks (${rc2}): ${e2}")
  endif()
  file(GLOB written ${OUT}/one/* ${OUT}/two/*)
  if(written)
    message(FATAL_ERROR "a failed export wrote ${written}")
  endif()
  message(STATUS "same error on 1 and 2 ranks: ${l2}")
  return()
endif()
execute_process(COMMAND ${WHIRL} ${args} --out ${OUT}/one RESULT_VARIABLE rc1 OUTPUT_VARIABLE o1 ERROR_VARIABLE e1)
if(NOT rc1 EQUAL 0)
  message(FATAL_ERROR "one process failed (${rc1}): ${o1} ${e1}")
endif()
execute_process(COMMAND ${MPIEXEC} -n 2 --oversubscribe ${WHIRL} ${args} --out ${OUT}/two
  RESULT_VARIABLE rc2 OUTPUT_VARIABLE o2 ERROR_VARIABLE e2)
if(NOT rc2 EQUAL 0)
  message(FATAL_ERROR "mpirun -n 2 failed (${rc2}): ${o2} ${e2}")
endif()
if(NOT o2 MATCHES "on 2 MPI ranks")
  message(FATAL_ERROR "the 2-rank run did not run on 2 ranks: ${o2}")
endif()
file(GLOB files RELATIVE ${OUT}/one ${OUT}/one/*)
file(GLOB files_two RELATIVE ${OUT}/two ${OUT}/two/*)
list(LENGTH files nfiles)
if(NOT nfiles EQUAL NFILES OR NOT files STREQUAL files_two)
  message(FATAL_ERROR "expected ${NFILES} files in both runs; one process: ${files}; 2 ranks: ${files_two}")
endif()
foreach(f ${files})
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/one/${f} ${OUT}/two/${f} RESULT_VARIABLE diff)
  if(NOT diff EQUAL 0)
    message(FATAL_ERROR "${f} differs between 1 and 2 ranks")
  endif()
endforeach()
message(STATUS "identical on 1 and 2 ranks: ${files}")
