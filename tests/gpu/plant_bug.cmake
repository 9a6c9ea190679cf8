# Script mode (cmake -P): a copy of shaders/ and common/shared/ under COPY_DIR with one planted
# bug, the text FROM replaced by TO in FILE (relative to the source root), for the debugging
# tests (debug_workflow_test.cpp). FROM must occur exactly once: when the source changes under
# a bug, the build stops here instead of compiling a shader without it.
file(REMOVE_RECURSE ${COPY_DIR})
file(COPY ${ROOT}/shaders DESTINATION ${COPY_DIR})
file(COPY ${ROOT}/common/shared DESTINATION ${COPY_DIR}/common)
file(READ ${COPY_DIR}/${FILE} text)
string(LENGTH "${text}" before)
string(REPLACE "${FROM}" "" without "${text}")
string(LENGTH "${without}" after)
string(LENGTH "${FROM}" from_length)
math(EXPR count "(${before} - ${after}) / ${from_length}")
if(NOT count EQUAL 1)
  message(FATAL_ERROR "planted bug: '${FROM}' occurs ${count} times in ${FILE}, not once")
endif()
string(REPLACE "${FROM}" "${TO}" text "${text}")
file(WRITE ${COPY_DIR}/${FILE} "${text}")
