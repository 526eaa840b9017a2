# Shared by the *_ranks.cmake scripts: runs `WHIRL <args> --out OUT/one` on one process and
# `MPIEXEC -n 2 --oversubscribe WHIRL <args> --out OUT/two`, and fails unless both succeed and the
# second really ran on 2 ranks.
function(run_one_and_two)
  execute_process(COMMAND ${WHIRL} ${ARGN} --out ${OUT}/one RESULT_VARIABLE rc1 OUTPUT_VARIABLE o1 ERROR_VARIABLE e1)
  if(NOT rc1 EQUAL 0)
    message(FATAL_ERROR "one process failed (${rc1}): ${o1} ${e1}")
  endif()
  execute_process(COMMAND ${MPIEXEC} -n 2 --oversubscribe ${WHIRL} ${ARGN} --out ${OUT}/two
    RESULT_VARIABLE rc2 OUTPUT_VARIABLE o2 ERROR_VARIABLE e2)
  if(NOT rc2 EQUAL 0)
    message(FATAL_ERROR "mpirun -n 2 failed (${rc2}): ${o2} ${e2}")
  endif()
  if(NOT o2 MATCHES "on 2 MPI ranks")
    message(FATAL_ERROR "the 2-rank run did not run on 2 ranks: ${o2}")
  endif()
endfunction()
