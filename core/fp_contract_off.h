// Switches floating-point contraction (fusing a*b+c into an fma) off for the rest of the
// translation unit. Include it first, before expansion_arithmetic.h or anything that includes it:
// the error-free transformations, the predicates' error bounds and Dekker's product rely on every
// product and sum being rounded on its own, and GCC's pragma only affects the functions defined
// after it. (No include guard: the pragma must be seen by every file that includes this one.)

#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif
