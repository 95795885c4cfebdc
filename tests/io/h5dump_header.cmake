# Runs `h5dump -H` on a sample run.h5 and checks that the standard tool reads the
# documented layout. Usage: cmake -DH5DUMP=... -DFILE=.../run.h5 -P h5dump_header.cmake
execute_process(COMMAND ${H5DUMP} -H ${FILE}
  RESULT_VARIABLE status OUTPUT_VARIABLE header ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "h5dump -H ${FILE} failed (${status}): ${errors}")
endif()
foreach(expected
    "GROUP \"h5md\""
    "ATTRIBUTE \"version\""
    "GROUP \"creator\""
    "GROUP \"author\""
    "DATASET \"as_given\""
    "DATASET \"resolved\""
    "GROUP \"particles\""
    "GROUP \"position\""
    "GROUP \"velocity\""
    "GROUP \"species\""
    "GROUP \"id\""
    "GROUP \"count\""
    "GROUP \"radius\""
    "GROUP \"angular_velocity\""
    "GROUP \"xdmf\""
    "DATASET \"species_radius\""
    "( 4, 12, 2 ) / ( H5S_UNLIMITED, H5S_UNLIMITED, 2 )"
    "( 4, 12 ) / ( H5S_UNLIMITED, H5S_UNLIMITED )"
    "( 4 ) / ( H5S_UNLIMITED )"
    "GROUP \"observables\""
    "GROUP \"kinetic_energy\""
    "GROUP \"deleted_inlet\"")
  string(FIND "${header}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "h5dump -H ${FILE}: no '${expected}' in\n${header}")
  endif()
endforeach()
message(STATUS "h5dump reads ${FILE}")
