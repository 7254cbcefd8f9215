# cmake -DSPV=in.spv -DCPP=out.cpp -DNAME=name -P EmbedSpirv.cmake
# Writes the SPIR-V words as a C++ array, so the executable needs no shader files at run time.
file(READ ${SPV} hex HEX)
string(LENGTH "${hex}" len)
math(EXPR bytes "${len} / 2")
math(EXPR rem "${bytes} % 4")
if(NOT rem EQUAL 0)
  message(FATAL_ERROR "${SPV}: size ${bytes} is not a whole number of 32-bit words")
endif()
math(EXPR words "${bytes} / 4")
# Little-endian bytes b0 b1 b2 b3 -> 0xb3b2b1b0
string(REGEX REPLACE "([0-9a-f][0-9a-f])([0-9a-f][0-9a-f])([0-9a-f][0-9a-f])([0-9a-f][0-9a-f])"
       "0x\\4\\3\\2\\1u," body "${hex}")
string(REGEX REPLACE "((0x[0-9a-f]+u,){8})" "\\1\n" body "${body}")
file(WRITE ${CPP} "// Generated from ${SPV}. Do not edit.
#include <cstddef>
#include <cstdint>
namespace penumbra::gpu::embedded {
extern const std::uint32_t spv_${NAME}[] = {
${body}
};
extern const std::size_t spv_${NAME}_words = ${words};
}
")
