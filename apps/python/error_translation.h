#pragma once
// The command line's exit statuses as Python exceptions, with the same one-line messages.
#include <exception>

namespace touchdown::python {

// Bad input (exit 2) as ValueError, an input file or a path the OS refused (2) as OSError (an
// input file not found: FileNotFoundError, with errno), a failed solver (3) as RuntimeError; the
// command line's option names as the Python function's argument names. For
// py::register_exception_translator.
void TranslateErrors(std::exception_ptr error);

}  // namespace touchdown::python
