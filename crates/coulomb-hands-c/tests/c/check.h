/* What the C tests share: a failing check prints where and the library's last error. */
#ifndef CHECK_H
#define CHECK_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "coulomb_hands.h"

static int failures = 0;

/* The thread's last error message, or "" (a static buffer). */
static const char *last_error(void) {
  static char message[1024];
  size_t needed = 0;
  message[0] = 0;
  if (ch_last_error(message, sizeof message, &needed) != CH_STATUS_OK) return "(too long)";
  return message;
}

#define CHECK(cond, ...)                                                   \
  do {                                                                     \
    if (!(cond)) {                                                         \
      fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #cond); \
      fprintf(stderr, __VA_ARGS__);                                        \
      fprintf(stderr, " (last error: %s)\n", last_error());                \
      failures++;                                                          \
    }                                                                      \
  } while (0)

/* A call that must succeed; its status otherwise, with the message. */
#define OK(call) CHECK((call) == CH_STATUS_OK, "%s", #call)

#endif
