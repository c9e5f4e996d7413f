/* Checks shared by the C ABI tests: CHECK(cond, fmt, ...) counts and reports a failure,
 * OK(call) checks a call returned SHEAF_OK and prints the ABI's message when not. */
#ifndef SHEAF_TESTS_CAPI_CHECK_H
#define SHEAF_TESTS_CAPI_CHECK_H

#include <sheaf/sheaf.h>

#include <stdio.h>

static int g_failures = 0;
static int g_checks = 0;

#define CHECK(cond, ...)                                                                           \
    do {                                                                                           \
        ++g_checks;                                                                                \
        if (!(cond)) {                                                                             \
            ++g_failures;                                                                          \
            fprintf(stderr, "FAILED %s:%d: %s: ", __FILE__, __LINE__, #cond);                      \
            fprintf(stderr, __VA_ARGS__);                                                          \
            fprintf(stderr, "\n");                                                                 \
        }                                                                                          \
    } while (0)

/* Calls that must succeed; on failure prints the ABI's message. */
#define OK(call)                                                                                   \
    do {                                                                                           \
        SheafError ok_err_ = (call);                                                               \
        const char* ok_msg_ = NULL;                                                                \
        if (ok_err_ != SHEAF_OK) sheafGetLastError(&ok_msg_);                                      \
        CHECK(ok_err_ == SHEAF_OK, "%s returned %d: %s", #call, (int)ok_err_,                      \
              ok_msg_ ? ok_msg_ : "");                                                             \
    } while (0)

#endif
