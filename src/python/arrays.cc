#include "python/arrays.h"

#include <cmath>
#include <limits>

#include "ga/genome.h"

namespace hexgait::python {

namespace {

// The array's shape as (rows, genes), or ValueError.
void CheckShape(const py::array& a, int genes, const char* name, int* rows) {
  const std::string expected = "(n, " + std::to_string(genes) + ")";
  if (a.ndim() == 1 && a.shape(0) == genes) {
    *rows = 1;
    return;
  }
  if (a.ndim() != 2 || a.shape(1) != genes) {
    std::string shape = "(";
    for (py::ssize_t d = 0; d < a.ndim(); ++d) {
      shape += (d ? ", " : "") + std::to_string(a.shape(d));
    }
    shape += a.ndim() == 1 ? ",)" : ")";
    throw py::value_error(std::string(name) + " must have shape " + expected + ", got " + shape);
  }
  if (a.shape(0) > std::numeric_limits<int>::max() / genes) {
    throw py::value_error(std::string(name) + " has too many rows");
  }
  *rows = static_cast<int>(a.shape(0));
}

// Lists and tuples are welcome; anything NumPy cannot read as an array is a TypeError.
py::array AsArray(const py::handle& object, const char* name) {
  py::array a = py::array::ensure(object);  // empty, with the error cleared, on failure
  if (!a) throw py::type_error(std::string(name) + " must be a NumPy array or a list of numbers");
  return a;
}

std::string Dtype(const py::array& a) {
  return py::str(a.dtype()).cast<std::string>();
}

}  // namespace

std::vector<int8_t> GenesFromArray(const py::handle& object, int genes, const char* name,
                                   int* rows) {
  const py::array a = AsArray(object, name);
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u') {
    throw py::type_error(std::string(name) + " must be an integer array (genes in [" +
                         std::to_string(kGeneMin) + ", " + std::to_string(kGeneMax) + "]), got " +
                         Dtype(a) + "; use evaluate_offsets for real-valued offsets");
  }
  CheckShape(a, genes, name, rows);
  std::vector<int8_t> out(static_cast<size_t>(*rows) * genes);
  const auto outside = [&](size_t i, const std::string& value) {
    return py::value_error(std::string(name) + "[" + std::to_string(i / genes) + ", " +
                           std::to_string(i % genes) + "] is " + value + ", outside [" +
                           std::to_string(kGeneMin) + ", " + std::to_string(kGeneMax) + "]");
  };
  if (kind == 'u') {
    // Read unsigned as unsigned: a uint64 above 2^63 cast to a signed type would wrap into a
    // small negative number, a valid gene.
    const auto values =
        py::array_t<unsigned long long, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!values) throw py::type_error(std::string(name) + ": cannot read as integers");
    const unsigned long long* data = values.data();
    for (size_t i = 0; i < out.size(); ++i) {
      if (data[i] > static_cast<unsigned long long>(kGeneMax)) {
        throw outside(i, std::to_string(data[i]));
      }
      out[i] = static_cast<int8_t>(data[i]);
    }
    return out;
  }
  const auto values = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!values) throw py::type_error(std::string(name) + ": cannot read as integers");
  const long long* data = values.data();
  for (size_t i = 0; i < out.size(); ++i) {
    if (data[i] < kGeneMin || data[i] > kGeneMax) throw outside(i, std::to_string(data[i]));
    out[i] = static_cast<int8_t>(data[i]);
  }
  return out;
}

std::vector<double> OffsetsFromArray(const py::handle& object, int genes, const char* name,
                                     int* rows) {
  const py::array a = AsArray(object, name);
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw py::type_error(std::string(name) + " must be a real array of rest-length offsets, got " +
                         Dtype(a));
  }
  CheckShape(a, genes, name, rows);
  const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!values) throw py::type_error(std::string(name) + ": cannot read as numbers");
  std::vector<double> out(values.data(), values.data() + static_cast<size_t>(*rows) * genes);
  for (size_t i = 0; i < out.size(); ++i) {
    if (!std::isfinite(out[i])) {
      throw py::value_error(std::string(name) + "[" + std::to_string(i / genes) + ", " +
                            std::to_string(i % genes) + "] is " +
                            (std::isnan(out[i]) ? "NaN" : "infinite") + "; offsets must be finite");
    }
  }
  return out;
}

py::dict ResultsToDict(std::span<const RunResult> results, int legs) {
  const auto n = static_cast<py::ssize_t>(results.size());
  py::dict d;
  ForEachResultField([&](const char* name, auto get) {
    py::array_t<decltype(get(RunResult{}))> values(n);
    for (py::ssize_t i = 0; i < n; ++i) values.mutable_at(i) = get(results[static_cast<size_t>(i)]);
    d[name] = values;
  });
  py::array_t<double> duty({n, static_cast<py::ssize_t>(legs)});
  for (py::ssize_t i = 0; i < n; ++i) {
    for (int leg = 0; leg < legs; ++leg) {
      duty.mutable_at(i, leg) = results[static_cast<size_t>(i)].DutyFactor(leg);
    }
  }
  d["duty_factors"] = duty;
  return d;
}

py::dict ResultToDict(const RunResult& result, int legs) {
  py::dict d;
  ForEachResultField([&](const char* name, auto get) { d[name] = get(result); });
  py::list duty;
  for (int leg = 0; leg < legs; ++leg) duty.append(result.DutyFactor(leg));
  d["duty_factors"] = duty;
  if (!result.fell) {
    d["fall_time"] = py::none();
    d["fall_cycle"] = py::none();
  }
  return d;
}

}  // namespace hexgait::python
