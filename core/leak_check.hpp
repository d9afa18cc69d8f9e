#pragma once
// LeakSanitizer (CHUTE_SANITIZE builds, scripts/test-sanitizers.sh): OpenMPI and hypre allocate blocks in
// MPI_Init/HYPRE_Init and MPI_Finalize/HYPRE_Finalize that they never free. Those calls run between
// CHUTE_LSAN_IGNORE_BEGIN and CHUTE_LSAN_IGNORE_END, with leak tracking off; everything allocated in between
// is checked. Used by every main() (the chute tool, the test runner).
#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#define CHUTE_LSAN_IGNORE_BEGIN __lsan_disable()
#define CHUTE_LSAN_IGNORE_END __lsan_enable()
#else
#define CHUTE_LSAN_IGNORE_BEGIN
#define CHUTE_LSAN_IGNORE_END
#endif
