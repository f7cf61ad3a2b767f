// What a fuzz target accepts from the code under test: input and file
// errors. Any other exception is a finding, reported before aborting.
#pragma once

#include "core/errors.h"

#include <cstdio>    // for std::fprintf
#include <cstdlib>   // for std::abort
#include <exception> // for std::exception

namespace meshpaint::fuzz {

//! Runs `work`; returns on success, InputError or IOError, aborts (a finding)
//! on any other exception, naming it.
template <class Work>
void expect_input_errors(Work&& work)
{
  try {
    work();
  } catch (const InputError&) {
  } catch (const IOError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unexpected exception: %s\n", e.what());
    std::abort();
  }
}

} // namespace meshpaint::fuzz
