/* test_fuzz_corpus.c -- cmocka suite that replays the committed corpus of
   every libFuzzer harness (each file of fuzz/corpus/<name>/) through the harness's own
   contract checks                                 -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_fuzz_corpus.c -lcmocka -lm
   (add -DVLBE_USE_FLOAT for the float build; the same source passes in both)

   Each harness fuzz/fuzz_<name>.c is included with its entry point renamed
   (LLVMFuzzerTestOneInput -> vlbe_fuzz_<name>_one) and built with
   VLBE_FUZZ_REPLAY, so that a failed FUZZ_CHECK calls
   vlbe_fuzz_fail_hook() below instead of abort(): the hook records the
   harness, file, line, message and call context and longjmps back to the
   replay loop, which goes on with the next file and fails the test at the
   end, naming every failing file.  Tests run from the repository root
   (make test), where fuzz/corpus/ is.  No tolerances here: the harnesses
   state theirs (fuzz_lu.c: backward-error bounds (4n + 4) eps |L||U| and
   (6n + 6) eps |L||U||x|; the rest are exact: finite / bitwise unchanged).

   Tests (one per harness): lu, ale, ale3, rancf, cr2d, chain, step.
   VLBE_TEST_REPORT=1 prints the number of inputs each replayed (a test
   fails when its corpus directory is missing or empty).
   Seeds named known_* and found_* reproduce contract violations of 77b73ad
   (fuzz/seeds.py): regression inputs, each failed here on that code;
   good_* passed there too. */
#define _POSIX_C_SOURCE 200809L
#include "test_util.h"

#include <dirent.h>

#define VLBE_FUZZ_REPLAY 1

#define LLVMFuzzerTestOneInput vlbe_fuzz_lu_one
#include "../fuzz/fuzz_lu.c"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput vlbe_fuzz_ale_one
#include "../fuzz/fuzz_ale.c"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput vlbe_fuzz_ale3_one
#include "../fuzz/fuzz_ale3.c"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput vlbe_fuzz_rancf_one
#include "../fuzz/fuzz_rancf.c"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput vlbe_fuzz_cr2d_one
#include "../fuzz/fuzz_cr2d.c"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput vlbe_fuzz_chain_one
#include "../fuzz/fuzz_chain.c"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput vlbe_fuzz_step_one
#include "../fuzz/fuzz_step.c"
#undef LLVMFuzzerTestOneInput

#define FZT_MAXIN 65536 /* largest corpus file replayed */

static jmp_buf fzt_jmp;
static char fzt_msg[512];

void vlbe_fuzz_fail_hook(const char *harness, const char *file, int line, const char *msg,
                         const char *ctx)
{
    snprintf(fzt_msg, sizeof fzt_msg, "[%s] %s:%d: %s (in %s)", harness, file, line, msg, ctx);
    longjmp(fzt_jmp, 1);
}

typedef int (*fzt_one)(const uint8_t *data, size_t size);

/* Replays every regular file of fuzz/corpus/<name>/; fails after the loop
   if any input violated the contract, listing them. */
static void fzt_replay(const char *name, fzt_one one)
{
    static uint8_t buf[FZT_MAXIN];
    char dir[256], path[512];
    DIR *d;
    struct dirent *de;
    volatile int nrun = 0, nfail = 0; /* live across the longjmp */
    snprintf(dir, sizeof dir, "fuzz/corpus/%s", name);
    d = opendir(dir);
    if (!d) fail_msg("corpus directory %s not found (run from the repository root)", dir);
    while ((de = readdir(d)) != NULL) {
        FILE *f;
        size_t n;
        if (de->d_name[0] == '.') continue;
        snprintf(path, sizeof path, "%s/%s", dir, de->d_name);
        f = fopen(path, "rb");
        if (!f) continue;
        n = fread(buf, 1, sizeof buf, f);
        fclose(f);
        ++nrun;
        if (setjmp(fzt_jmp) == 0) {
            one(buf, n);
        } else {
            ++nfail;
            print_message("corpus %s: %s\n", path, fzt_msg);
        }
    }
    closedir(d);
    if (nrun == 0) fail_msg("corpus %s: no inputs", dir);
    if (tu_report_on()) {
        char key[64];
        print_message("    corpus %s: %d inputs replayed\n", dir, (int)nrun);
        snprintf(key, sizeof key, "inputs_%s", name);
        tu_measured(key, (double)nrun);
    }
    if (nfail) fail_msg("corpus %s: %d of %d inputs violate the contract (listed above)", dir, (int)nfail,
                 (int)nrun);
}

static void test_lu(void **state)
{
    (void)state;
    fzt_replay("lu", vlbe_fuzz_lu_one);
}
static void test_ale(void **state)
{
    (void)state;
    fzt_replay("ale", vlbe_fuzz_ale_one);
}
static void test_ale3(void **state)
{
    (void)state;
    fzt_replay("ale3", vlbe_fuzz_ale3_one);
}
static void test_rancf(void **state)
{
    (void)state;
    fzt_replay("rancf", vlbe_fuzz_rancf_one);
}
static void test_cr2d(void **state)
{
    (void)state;
    fzt_replay("cr2d", vlbe_fuzz_cr2d_one);
}
static void test_chain(void **state)
{
    (void)state;
    fzt_replay("chain", vlbe_fuzz_chain_one);
}
static void test_step(void **state)
{
    (void)state;
    fzt_replay("step", vlbe_fuzz_step_one);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lu),    cmocka_unit_test(test_ale),   cmocka_unit_test(test_ale3),
        cmocka_unit_test(test_rancf), cmocka_unit_test(test_cr2d),  cmocka_unit_test(test_chain),
        cmocka_unit_test(test_step),
    };
    return cmocka_run_group_tests_name("fuzz_corpus", tests, NULL, NULL);
}
