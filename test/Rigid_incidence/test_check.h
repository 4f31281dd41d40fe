// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The CHECK macro of the test programs: counts checks and failures, prints the first failures
// (80, or $RI_TEST_MAX_MESSAGES) with their line, counts the others.

#ifndef RIGID_INCIDENCE_TEST_CHECK_H
#define RIGID_INCIDENCE_TEST_CHECK_H

#include <cstdlib>
#include <iostream>

static int failures = 0;
static long checks = 0;
static const int max_messages = std::getenv("RI_TEST_MAX_MESSAGES") ? std::atoi(std::getenv("RI_TEST_MAX_MESSAGES")) : 80;
#define CHECK(cond, msg)                                                                                   \
  do {                                                                                                     \
    ++checks;                                                                                              \
    if (!(cond) && ++failures <= max_messages) std::cerr << "FAIL (line " << __LINE__ << ") " << msg << "\n"; \
  } while (0)

#endif
