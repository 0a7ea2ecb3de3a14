# Writes the core's size limits (src/size_limits.h) as a TypeScript module, so that the importers
# (web/src/rig/rig_limits.ts) and the API refuse what the core refuses without a second copy.
# Run as: cmake -DHEADER=size_limits.h -DOUTPUT=size_limits.ts -P size_limits_ts.cmake
# Every `constexpr <type> kName = <value>;` line becomes `kName: <value>,`; an integer value is
# evaluated here (64-bit: `2LL << 30` is 2147483648, which JavaScript's 32-bit shift would not give).
file(STRINGS ${HEADER} lines REGEX "^constexpr (int|long long|double) k[A-Za-z]+ = [^;]+;")
set(body "")
foreach(line IN LISTS lines)
  string(REGEX REPLACE "^constexpr ([a-z ]+) (k[A-Za-z]+) = ([^;]+);.*$" "\\1;\\2;\\3" parts "${line}")
  list(GET parts 0 type)
  list(GET parts 1 name)
  list(GET parts 2 value)
  if(type STREQUAL "double")
    set(number "${value}")
  else()
    string(REPLACE "LL" "" expression "${value}")
    math(EXPR number "${expression}")
  endif()
  string(APPEND body "  ${name}: ${number},\n")
endforeach()
file(WRITE ${OUTPUT}.tmp "// Generated from wasm/src/size_limits.h by wasm/cmake/size_limits_ts.cmake: edit the header.\n"
  "// The largest problems the core accepts (the header says why each is what it is).\n"
  "export const SIZE_LIMITS = {\n${body}} as const;\n")
# Rewritten only when it changes, so that nothing rebuilds for nothing.
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.tmp)
