#pragma once
/// @brief Small RAII handles over the HDF5 C API: files, groups, datasets, dataspaces, property lists.
///
/// Each handle owns one hid_t and closes it with the matching H5*close call; handles move, never
/// copy. Every call that can fail is checked and throws std::runtime_error naming the operation,
/// the file and the object (dataset, group or attribute), so a failed write says what it was
/// writing where. Files open serially (sec2 driver, any process on its own) or collectively over a
/// Comm (MPI-IO driver; every rank of the Comm must then make the same create/open calls in the same
/// order). Attributes are small arrays of double or int64 stored on a file, group or dataset.
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

#include "core/parallel/comm.h"

namespace mpmice::core {

/// Throws std::runtime_error("HDF5: <what> failed (file '<file>', object '<object>')") if status < 0.
void h5Check(herr_t status, const std::string& what, const std::string& file, const std::string& object);

/// One owned hid_t, closed by the function given at construction.
class H5Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  H5Handle() = default;
  /// Takes ownership of id; throws (naming what, file, object) when id < 0.
  H5Handle(hid_t id, Closer closer, const std::string& what, const std::string& file,
           const std::string& object);
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
  H5Handle(H5Handle&& o) noexcept { swap(o); }
  H5Handle& operator=(H5Handle&& o) noexcept {
    H5Handle tmp(std::move(o));
    swap(tmp);
    return *this;
  }
  ~H5Handle() { reset(); }

  [[nodiscard]] hid_t id() const { return id_; }
  [[nodiscard]] bool valid() const { return id_ >= 0; }
  void reset();

 private:
  void swap(H5Handle& o) noexcept;
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

/// A dataspace: simple (with dims) or scalar.
class H5Dataspace : public H5Handle {
 public:
  H5Dataspace() = default;
  explicit H5Dataspace(hid_t id, const std::string& file = "", const std::string& object = "");
  static H5Dataspace simple(const std::vector<hsize_t>& dims, const std::string& file = "",
                            const std::string& object = "");
  static H5Dataspace scalar();
  [[nodiscard]] std::vector<hsize_t> dims() const;
  /// Selects the block start..start+count (replacing any selection); an empty count selects none.
  void selectBlock(const std::vector<hsize_t>& start, const std::vector<hsize_t>& count);
  void selectNone();
};

/// A property list (file access, dataset transfer, link creation, ...).
class H5PropList : public H5Handle {
 public:
  explicit H5PropList(hid_t cls);
  /// File access over MPI-IO on comm.
  static H5PropList fileAccessMpio(const Comm& comm);
  /// Dataset transfer, collective (true) or independent MPI-IO.
  static H5PropList transferMpio(bool collective);
};

/// A dataset of doubles.
class H5Dataset : public H5Handle {
 public:
  H5Dataset(hid_t id, std::string file, std::string name);
  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] H5Dataspace space() const;
  /// Writes buf (laid out as the selection, C order) into the selection of the file space.
  /// With dxpl collective every rank of the file's Comm must call, possibly with an empty selection.
  void write(const double* buf, const H5Dataspace& mem, const H5Dataspace& fileSel, hid_t dxpl) const;
  void read(double* buf, const H5Dataspace& mem, const H5Dataspace& fileSel, hid_t dxpl) const;

 private:
  std::string file_, name_;
};

/// A group (or the file's root group "/").
class H5Group : public H5Handle {
 public:
  H5Group(hid_t id, std::string file, std::string name);
  [[nodiscard]] const std::string& name() const { return name_; }
  /// Creates (or opens, when present) the subgroup; nested paths "a/b" are created level by level.
  [[nodiscard]] H5Group group(const std::string& path) const;
  [[nodiscard]] H5Group openGroup(const std::string& path) const;
  [[nodiscard]] bool has(const std::string& name) const;
  /// Names of the direct members (datasets and groups), in name order.
  [[nodiscard]] std::vector<std::string> members() const;
  /// Creates a dataset of doubles with the given global dims.
  [[nodiscard]] H5Dataset createDataset(const std::string& name, const std::vector<hsize_t>& dims) const;
  [[nodiscard]] H5Dataset openDataset(const std::string& name) const;

  void writeAttribute(const std::string& name, const std::vector<double>& v) const;
  void writeAttribute(const std::string& name, const std::vector<std::int64_t>& v) const;
  /// A UTF-8 text as a scalar fixed-length string attribute (h5py: bytes, .decode()).
  void writeAttribute(const std::string& name, const std::string& text) const;
  [[nodiscard]] bool hasAttribute(const std::string& name) const;
  [[nodiscard]] std::vector<double> readAttributeDouble(const std::string& name) const;
  [[nodiscard]] std::vector<std::int64_t> readAttributeInt(const std::string& name) const;
  [[nodiscard]] std::string readAttributeString(const std::string& name) const;

 private:
  std::string path(const std::string& child) const;
  std::string file_, name_;
};

/// An HDF5 file, created (truncating) or opened read-only, serially or collectively.
class H5File : public H5Handle {
 public:
  static H5File create(const std::string& path);
  static H5File create(const Comm& comm, const std::string& path);
  static H5File open(const std::string& path);
  static H5File open(const Comm& comm, const std::string& path);

  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] bool parallel() const { return parallel_; }
  [[nodiscard]] H5Group root() const;

 private:
  H5File(hid_t id, std::string path, bool parallel);
  std::string path_;
  bool parallel_ = false;
};

}  // namespace mpmice::core
