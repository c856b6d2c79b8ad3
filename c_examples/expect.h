/* The checks of the C bad-input and randomized tests (strict C99), shared by bad_input.c,
 * contact_bad_input.c, solid_contact_bad_input.c and solid_randomized.c:
 *
 *   EXPECT(cond)                       in a `bool test_x(void)`: print the failed condition
 *                                      with its file and line and return false
 *   status_is_in(got, want, fn, part)  the call returned `want`, the last error message
 *                                      contains `part` (unless NULL), an error's message starts
 *                                      with the function's name `fn` (unless NULL), and a
 *                                      success left no message
 *   STATUS(call, want, part)           status_is_in without the function's name
 *   STATUS_FN(fn, args, want, part)    calls `fn args` and checks that the message names `fn`
 *   fill / untouched                   doubles set to, and still holding, EXPECT_SENTINEL
 *   fill_bytes / bytes_untouched       any buffer set to, and still holding, bytes 0xA5
 *   MARKER(type)                       a non-NULL pointer a failed `_new` must leave in place
 *
 * Everything is `static inline` so a test that uses a part only compiles without an unused-
 * function warning. */
#ifndef HYCON_EXAMPLES_EXPECT_H
#define HYCON_EXAMPLES_EXPECT_H

#include "hycon.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#define EXPECT(cond)                                                                           \
    do {                                                                                       \
        if (!(cond)) {                                                                         \
            fprintf(stderr, "  %s:%d: expectation failed: %s\n", __FILE__, __LINE__, #cond);   \
            return false;                                                                      \
        }                                                                                      \
    } while (0)

/* The call returned `want` and the last error message contains `part` (and, for an error,
 * starts with the function's name `fn`; a success leaves no message). */
static inline bool status_is_in(HyconStatus got, HyconStatus want, const char *fn,
                                const char *part) {
    char message[1024];
    hycon_last_error_message(message, sizeof message);
    if (got != want) {
        fprintf(stderr, "  got %s (%d), expected %s: \"%s\"\n", hycon_status_name(got), (int)got,
                hycon_status_name(want), message);
        return false;
    }
    if (part != NULL && strstr(message, part) == NULL) {
        fprintf(stderr, "  message \"%s\" lacks \"%s\"\n", message, part);
        return false;
    }
    if (want != HYCON_OK && fn != NULL && strstr(message, fn) != message) {
        fprintf(stderr, "  message \"%s\" does not start with the function name %s\n", message,
                fn);
        return false;
    }
    if (want == HYCON_OK && message[0] != '\0') {
        fprintf(stderr, "  success left the message \"%s\"\n", message);
        return false;
    }
    return true;
}
#define STATUS(call, want, part) status_is_in((call), (want), NULL, (part))
/* as STATUS, and the message starts with the name of the function called */
#define STATUS_FN(fn, args, want, part) status_is_in(fn args, (want), #fn, (part))

/* Outputs a failed call must leave as they were. */
#define EXPECT_SENTINEL 12345.0
#define EXPECT_SENTINEL_BYTE 0xA5

static inline void fill(double *a, size_t n) {
    size_t i;
    for (i = 0; i < n; ++i) a[i] = EXPECT_SENTINEL;
}
static inline bool untouched(const double *a, size_t n) {
    size_t i;
    for (i = 0; i < n; ++i)
        if (a[i] != EXPECT_SENTINEL) return false;
    return true;
}
static inline void fill_bytes(void *p, size_t n) { memset(p, EXPECT_SENTINEL_BYTE, n); }
static inline bool bytes_untouched(const void *p, size_t n) {
    const unsigned char *b = (const unsigned char *)p;
    size_t i;
    for (i = 0; i < n; ++i)
        if (b[i] != EXPECT_SENTINEL_BYTE) return false;
    return true;
}

/* A handle output initialised to this marker must still hold it after a failed `_new`. */
static inline char *expect_marker_storage(void) {
    static char storage;
    return &storage;
}
#define MARKER(type) ((type *)(void *)expect_marker_storage())

#endif
