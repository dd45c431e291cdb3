// boreas for Python: the exception classes (boreas.Error and one subclass per status, each
// also deriving from the built-in exception a Python user would catch) and the translation
// of StatusError and BindingError into them.
#include "errors.h"

#include <array>

namespace py = pybind11;

namespace boreas_py {
namespace {

constexpr int kStatusCount = BOREAS_ERROR_INTERNAL + 1;

// The classes, by status (index 0: boreas.Error itself). Created once, kept for the life of
// the process, like every class of an extension module.
std::array<PyObject*, kStatusCount> error_classes{};

struct ClassSpec {
  boreas_status status;
  const char* name;   // qualified, for __module__ and __qualname__
  PyObject* builtin;  // the second base, or nullptr
  const char* doc;
};

PyObject* new_class(const char* name, const char* doc, py::tuple bases, py::object status) {
  py::dict attrs;
  attrs["status"] = status;
  attrs["status_name"] =
      status.is_none() ? py::object(py::none())
                       : py::object(py::str(boreas_status_name(boreas_status(status.cast<int>()))));
  PyObject* cls = PyErr_NewExceptionWithDoc(name, doc, bases.ptr(), attrs.ptr());
  if (!cls) throw py::error_already_set();
  return cls;
}

// Sets the Python error; a translator returns after it.
void set_error(PyObject* cls, const std::string& message, py::object status) {
  // Messages may quote file contents or a device name cut mid-character: bytes that are
  // not UTF-8 are replaced rather than raising UnicodeDecodeError in place of the error.
  py::object text = py::reinterpret_steal<py::object>(
      PyUnicode_DecodeUTF8(message.data(), py::ssize_t(message.size()), "replace"));
  if (!text) throw py::error_already_set();
  py::object exc = py::reinterpret_borrow<py::object>(cls)(text);
  exc.attr("status") = status;
  exc.attr("status_name") =
      status.is_none() ? py::object(py::none())
                       : py::object(py::str(boreas_status_name(boreas_status(status.cast<int>()))));
  PyErr_SetObject(cls, exc.ptr());
}

}  // namespace

void register_errors(py::module_& m) {
  PyObject* base = new_class(
      "boreas.Error",
      "A boreas call failed.\n\n"
      "Attributes\n----------\n"
      "status : int or None\n"
      "    The C library's ``boreas_status`` code (1..8), or None for a failure of the\n"
      "    Python layer itself (a closed world, a callback calling into its own world).\n"
      "status_name : str or None\n"
      "    The status's C name, e.g. ``'BOREAS_ERROR_INVALID_ARGUMENT'``.\n\n"
      "The message is the library's ``boreas_last_error()``: it names the field, file or\n"
      "id that was wrong. After a failed call the world is left exactly as it was.",
      py::make_tuple(py::handle(PyExc_Exception)), py::none());
  error_classes[0] = base;
  m.add_object("Error", py::handle(base));

  const ClassSpec specs[] = {
      {BOREAS_ERROR_INVALID_ARGUMENT, "boreas.InvalidArgumentError", PyExc_ValueError,
       "An argument was out of range, NaN, of the wrong size, or otherwise refused\n"
       "(``BOREAS_ERROR_INVALID_ARGUMENT``). Also a ValueError."},
      {BOREAS_ERROR_NO_DEVICE, "boreas.NoDeviceError", nullptr,
       "No OpenCL platform, or no device matching the request (``BOREAS_ERROR_NO_DEVICE``)."},
      {BOREAS_ERROR_KERNEL_BUILD, "boreas.KernelBuildError", nullptr,
       "A kernel failed to compile; the message holds the build log\n"
       "(``BOREAS_ERROR_KERNEL_BUILD``)."},
      {BOREAS_ERROR_OPENCL, "boreas.OpenCLError", nullptr,
       "An OpenCL call failed at run time (``BOREAS_ERROR_OPENCL``)."},
      {BOREAS_ERROR_NOT_FOUND, "boreas.NotFoundError", PyExc_LookupError,
       "An id (a handle) that was removed, expired, or belongs to another world\n"
       "(``BOREAS_ERROR_NOT_FOUND``). Also a LookupError."},
      {BOREAS_ERROR_OUT_OF_MEMORY, "boreas.OutOfMemoryError", PyExc_MemoryError,
       "The host or the device ran out of memory, or an add would pass the device's limit\n"
       "(``BOREAS_ERROR_OUT_OF_MEMORY``). Also a MemoryError."},
      {BOREAS_ERROR_IO, "boreas.FileError", PyExc_OSError,
       "A file could not be read or written, or its contents are malformed\n"
       "(``BOREAS_ERROR_IO``). Also an OSError."},
      {BOREAS_ERROR_INTERNAL, "boreas.InternalError", nullptr,
       "A bug in boreas (``BOREAS_ERROR_INTERNAL``); please report it with the message."},
  };
  for (const ClassSpec& spec : specs) {
    py::tuple bases = spec.builtin ? py::make_tuple(py::handle(base), py::handle(spec.builtin))
                                   : py::make_tuple(py::handle(base));
    PyObject* cls = new_class(spec.name, spec.doc, bases, py::int_(int(spec.status)));
    error_classes[spec.status] = cls;
    m.add_object(spec.name + 7, py::handle(cls));  // without "boreas."
  }

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const StatusError& e) {
      int status = int(e.status());
      PyObject* cls =
          status > 0 && status < kStatusCount ? error_classes[status] : error_classes[0];
      set_error(cls, e.what(), py::int_(status));
    } catch (const BindingError& e) {
      set_error(error_classes[0], e.what(), py::none());
    }
  });
}

}  // namespace boreas_py
