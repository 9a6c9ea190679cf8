# Fails when a header of common/shared/ is missing from the GLSL compile test.
file(GLOB headers RELATIVE ${HEADER_DIR} ${HEADER_DIR}/*.h)
file(READ ${SHADER} shader)
foreach(h IN LISTS headers)
  string(FIND "${shader}" "#include \"shared/${h}\"" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "common/shared/${h} is not included by ${SHADER}")
  endif()
endforeach()
