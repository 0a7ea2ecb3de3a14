// Counts heap allocations made by this test binary (every malloc, which operator new and Eigen
// both use), so a test can prove that a piece of code allocates nothing.
#pragma once

namespace ik::test {

// The number of heap allocations made so far by the whole process.
long heap_allocations();

}  // namespace ik::test
