#include "error_translation.h"

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <regex>
#include <string>

#include <pybind11/pybind11.h>

#include "lander/integ/cvode_integrator.h"
#include "rft/input_error.h"
#include "rft/input_file.h"

namespace py = pybind11;

namespace touchdown::python {
namespace {

// An input file the OS would not open as the OSError subclass Python raises for its errno
// (FileNotFoundError, PermissionError, ...), with the command line's message and e.errno set.
void SetInputFileError(const InputFileError& e) {
  PyObject* type = e.os_error() == ENOENT || e.os_error() == ENOTDIR ? PyExc_FileNotFoundError
                   : e.os_error() == EACCES || e.os_error() == EPERM  ? PyExc_PermissionError
                   : e.os_error() == EISDIR                           ? PyExc_IsADirectoryError
                                                                      : PyExc_OSError;
  py::object exception = py::reinterpret_borrow<py::object>(type)(e.what());
  exception.attr("errno") = e.os_error();
  PyErr_SetObject(type, exception.ptr());
}

// A message of the shared library code names its inputs as the command line has them; from Python
// they are the function's arguments: `--samples` is `samples`, `--fit-on` is `fit_on`.
std::string WithPythonArgumentNames(const std::string& message) {
  static const std::regex flag(R"((^|[^-\w])--([a-z][a-z0-9-]*))");
  std::string out;
  auto begin = std::sregex_iterator(message.begin(), message.end(), flag);
  size_t last = 0;
  for (auto it = begin; it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    std::string name = m[2].str();
    std::replace(name.begin(), name.end(), '-', '_');
    out += message.substr(last, m.position(0) - last) + m[1].str() + name;
    last = m.position(0) + m.length(0);
  }
  return out + message.substr(last);
}

}  // namespace

// The command line's exit statuses as Python exceptions, with the same one-line messages:
// bad input (2) ValueError, an input file or a path the OS refused (2) OSError (an input file
// not found: FileNotFoundError), a failed solver (3) RuntimeError.
void TranslateErrors(std::exception_ptr error) {
  try {
    if (error) std::rethrow_exception(error);
  } catch (const InputFileError& e) {
    SetInputFileError(e);
  } catch (const InputError& e) {
    PyErr_SetString(PyExc_ValueError, WithPythonArgumentNames(e.what()).c_str());
  } catch (const integ::IntegrationFailure& e) {
    PyErr_SetString(PyExc_RuntimeError, (std::string("integration failed: ") + e.what()).c_str());
  } catch (const SolverFailure& e) {
    PyErr_SetString(PyExc_RuntimeError, e.what());
  } catch (const std::filesystem::filesystem_error& e) {
    const std::string path = e.path1().empty() ? std::string("a path") : e.path1().string();
    PyErr_SetString(PyExc_OSError, (path + ": " + e.code().message()).c_str());
  }
}

}  // namespace touchdown::python
