#pragma once
// Every allocation through operator new in the test programs is counted, so a test can show
// that an integration allocates nothing (tests/allocation_count.cpp).

namespace hertzdash::test {

/// Allocations through any operator new (plain, array, nothrow, aligned) so far.
long allocation_count();

}  // namespace hertzdash::test
