//! Tests of the C ABI, calling the extern functions as C does.
