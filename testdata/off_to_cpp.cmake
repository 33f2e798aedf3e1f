# SPDX-License-Identifier: BSD-3-Clause
# cmake -DINPUT=mesh.off -DOUTPUT=mesh.cpp -P off_to_cpp.cmake: a text OFF (triangles, '#'
# comments) as the arrays of stanford_bunny.h, its numbers copied as written.
file(STRINGS ${INPUT} lines)
set(counts "")
set(vertices "")
set(triangles "")
foreach(line IN LISTS lines)
  if(line MATCHES "^#" OR line STREQUAL "OFF" OR line STREQUAL "")
    continue()
  endif()
  string(REGEX REPLACE "[ \t]+" ";" words "${line}")
  if(NOT counts)
    set(counts ${words})
    list(GET counts 0 nv)
    list(GET counts 1 nt)
  elseif(NOT nv EQUAL 0)
    list(JOIN words ", " joined)
    string(APPEND vertices "    {${joined}},\n")
    math(EXPR nv "${nv} - 1")
  else()
    list(REMOVE_AT words 0)
    list(JOIN words ", " joined)
    string(APPEND triangles "    {${joined}},\n")
  endif()
endforeach()
list(GET counts 0 vertex_count)
list(GET counts 1 triangle_count)
file(WRITE ${OUTPUT} "// Generated from ${INPUT} by off_to_cpp.cmake.
#include \"stanford_bunny.h\"

namespace lsr {

const std::array<double, 3> kBunnyVertices[${vertex_count}] = {
${vertices}};

const std::array<int, 3> kBunnyTriangles[${triangle_count}] = {
${triangles}};

}  // namespace lsr
")
