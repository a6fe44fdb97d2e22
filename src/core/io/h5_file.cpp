#include "core/io/h5_file.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <utility>

namespace mpmice::core {

void h5Check(herr_t status, const std::string& what, const std::string& file, const std::string& object) {
  if (status < 0)
    throw std::runtime_error("HDF5: " + what + " failed (file '" + file + "', object '" + object + "')");
}

// ---- H5Handle -------------------------------------------------------------------------------

H5Handle::H5Handle(hid_t id, Closer closer, const std::string& what, const std::string& file,
                   const std::string& object)
    : id_(id), closer_(closer) {
  if (id < 0) {
    id_ = H5I_INVALID_HID;
    h5Check(-1, what, file, object);
  }
}

void H5Handle::reset() {
  if (id_ >= 0 && closer_) closer_(id_);
  id_ = H5I_INVALID_HID;
}

void H5Handle::swap(H5Handle& o) noexcept {
  std::swap(id_, o.id_);
  std::swap(closer_, o.closer_);
}

// ---- H5Dataspace ----------------------------------------------------------------------------

H5Dataspace::H5Dataspace(hid_t id, const std::string& file, const std::string& object)
    : H5Handle(id, H5Sclose, "opening a dataspace", file, object) {}

H5Dataspace H5Dataspace::simple(const std::vector<hsize_t>& dims, const std::string& file,
                                const std::string& object) {
  return H5Dataspace(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), file, object);
}

H5Dataspace H5Dataspace::scalar() { return H5Dataspace(H5Screate(H5S_SCALAR)); }

std::vector<hsize_t> H5Dataspace::dims() const {
  const int rank = H5Sget_simple_extent_ndims(id());
  h5Check(rank, "reading a dataspace rank", "", "");
  std::vector<hsize_t> d(static_cast<std::size_t>(rank));
  if (rank > 0) h5Check(H5Sget_simple_extent_dims(id(), d.data(), nullptr), "reading dataspace dims", "", "");
  return d;
}

void H5Dataspace::selectBlock(const std::vector<hsize_t>& start, const std::vector<hsize_t>& count) {
  for (hsize_t c : count)
    if (c == 0) return selectNone();
  h5Check(H5Sselect_hyperslab(id(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
          "selecting a hyperslab", "", "");
}

void H5Dataspace::selectNone() { h5Check(H5Sselect_none(id()), "clearing a selection", "", ""); }

// ---- H5PropList -----------------------------------------------------------------------------

H5PropList::H5PropList(hid_t cls) : H5Handle(H5Pcreate(cls), H5Pclose, "creating a property list", "", "") {}

H5PropList H5PropList::fileAccessMpio(const Comm& comm) {
  H5PropList p(H5P_FILE_ACCESS);
  h5Check(H5Pset_fapl_mpio(p.id(), comm.raw(), MPI_INFO_NULL), "H5Pset_fapl_mpio", "", "");
  return p;
}

H5PropList H5PropList::transferMpio(bool collective) {
  H5PropList p(H5P_DATASET_XFER);
  h5Check(H5Pset_dxpl_mpio(p.id(), collective ? H5FD_MPIO_COLLECTIVE : H5FD_MPIO_INDEPENDENT),
          "H5Pset_dxpl_mpio", "", "");
  return p;
}

// ---- H5Dataset ------------------------------------------------------------------------------

H5Dataset::H5Dataset(hid_t id, std::string file, std::string name)
    : H5Handle(id, H5Dclose, "opening dataset", file, name), file_(std::move(file)), name_(std::move(name)) {}

H5Dataspace H5Dataset::space() const { return H5Dataspace(H5Dget_space(id()), file_, name_); }

void H5Dataset::write(const double* buf, const H5Dataspace& mem, const H5Dataspace& fileSel, hid_t dxpl) const {
  h5Check(H5Dwrite(id(), H5T_NATIVE_DOUBLE, mem.id(), fileSel.id(), dxpl, buf), "writing dataset", file_, name_);
}

void H5Dataset::read(double* buf, const H5Dataspace& mem, const H5Dataspace& fileSel, hid_t dxpl) const {
  h5Check(H5Dread(id(), H5T_NATIVE_DOUBLE, mem.id(), fileSel.id(), dxpl, buf), "reading dataset", file_, name_);
}

// ---- H5Group --------------------------------------------------------------------------------

H5Group::H5Group(hid_t id, std::string file, std::string name)
    : H5Handle(id, H5Gclose, "opening group", file, name), file_(std::move(file)), name_(std::move(name)) {}

std::string H5Group::path(const std::string& child) const {
  return name_ == "/" ? "/" + child : name_ + "/" + child;
}

bool H5Group::has(const std::string& name) const {
  // Check each level: H5Lexists fails (rather than returning false) on a missing intermediate.
  std::string sofar;
  std::size_t pos = 0;
  while (pos <= name.size()) {
    const std::size_t next = name.find('/', pos);
    const std::string part = name.substr(pos, next == std::string::npos ? std::string::npos : next - pos);
    if (!part.empty()) {
      sofar += (sofar.empty() ? "" : "/") + part;
      if (H5Lexists(id(), sofar.c_str(), H5P_DEFAULT) <= 0) return false;
    }
    if (next == std::string::npos) break;
    pos = next + 1;
  }
  return true;
}

H5Group H5Group::group(const std::string& p) const {
  std::string sofar;
  std::size_t pos = 0;
  while (true) {
    const std::size_t next = p.find('/', pos);
    const std::string part = p.substr(pos, next == std::string::npos ? std::string::npos : next - pos);
    if (!part.empty()) {
      sofar += (sofar.empty() ? "" : "/") + part;
      if (H5Lexists(id(), sofar.c_str(), H5P_DEFAULT) <= 0) {
        H5Group created(H5Gcreate2(id(), sofar.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), file_,
                        path(sofar));
      }
    }
    if (next == std::string::npos) break;
    pos = next + 1;
  }
  return openGroup(p);
}

H5Group H5Group::openGroup(const std::string& p) const {
  if (!has(p)) throw std::runtime_error("HDF5: no group '" + path(p) + "' in file '" + file_ + "'");
  return H5Group(H5Gopen2(id(), p.c_str(), H5P_DEFAULT), file_, path(p));
}

namespace {
herr_t collectName(hid_t, const char* name, const H5L_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->emplace_back(name);
  return 0;
}
}  // namespace

std::vector<std::string> H5Group::members() const {
  std::vector<std::string> names;
  hsize_t idx = 0;
  h5Check(H5Literate(id(), H5_INDEX_NAME, H5_ITER_INC, &idx, collectName, &names), "listing members", file_,
          name_);
  return names;
}

H5Dataset H5Group::createDataset(const std::string& name, const std::vector<hsize_t>& dims) const {
  const H5Dataspace space = H5Dataspace::simple(dims, file_, path(name));
  return H5Dataset(H5Dcreate2(id(), name.c_str(), H5T_NATIVE_DOUBLE, space.id(), H5P_DEFAULT, H5P_DEFAULT,
                              H5P_DEFAULT),
                   file_, path(name));
}

H5Dataset H5Group::openDataset(const std::string& name) const {
  if (!has(name)) throw std::runtime_error("HDF5: no dataset '" + path(name) + "' in file '" + file_ + "'");
  return H5Dataset(H5Dopen2(id(), name.c_str(), H5P_DEFAULT), file_, path(name));
}

namespace {
template <class T>
void writeAttr(hid_t loc, hid_t type, const std::string& name, const std::vector<T>& v, const std::string& file,
               const std::string& obj) {
  if (H5Aexists(loc, name.c_str()) > 0) h5Check(H5Adelete(loc, name.c_str()), "replacing attribute " + name, file, obj);
  const H5Dataspace space = H5Dataspace::simple({static_cast<hsize_t>(v.size())}, file, obj);
  H5Handle attr(H5Acreate2(loc, name.c_str(), type, space.id(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                "creating attribute " + name, file, obj);
  h5Check(H5Awrite(attr.id(), type, v.data()), "writing attribute " + name, file, obj);
}

template <class T>
std::vector<T> readAttr(hid_t loc, hid_t type, const std::string& name, const std::string& file,
                        const std::string& obj) {
  if (H5Aexists(loc, name.c_str()) <= 0)
    throw std::runtime_error("HDF5: no attribute '" + name + "' on '" + obj + "' in file '" + file + "'");
  H5Handle attr(H5Aopen(loc, name.c_str(), H5P_DEFAULT), H5Aclose, "opening attribute " + name, file, obj);
  const H5Dataspace space(H5Aget_space(attr.id()), file, obj);
  const hssize_t n = H5Sget_simple_extent_npoints(space.id());
  h5Check(static_cast<herr_t>(n < 0 ? -1 : 0), "sizing attribute " + name, file, obj);
  std::vector<T> v(static_cast<std::size_t>(n));
  if (n > 0) h5Check(H5Aread(attr.id(), type, v.data()), "reading attribute " + name, file, obj);
  return v;
}
}  // namespace

void H5Group::writeAttribute(const std::string& name, const std::vector<double>& v) const {
  writeAttr(id(), H5T_NATIVE_DOUBLE, name, v, file_, name_);
}
void H5Group::writeAttribute(const std::string& name, const std::vector<std::int64_t>& v) const {
  writeAttr(id(), H5T_NATIVE_INT64, name, v, file_, name_);
}
void H5Group::writeAttribute(const std::string& name, const std::string& text) const {
  if (H5Aexists(id(), name.c_str()) > 0) h5Check(H5Adelete(id(), name.c_str()), "replacing attribute " + name, file_, name_);
  H5Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "string type of attribute " + name, file_, name_);
  h5Check(H5Tset_size(type.id(), std::max<std::size_t>(1, text.size())), "sizing attribute " + name, file_, name_);
  h5Check(H5Tset_strpad(type.id(), H5T_STR_NULLPAD), "padding attribute " + name, file_, name_);
  h5Check(H5Tset_cset(type.id(), H5T_CSET_UTF8), "character set of attribute " + name, file_, name_);
  H5Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space of attribute " + name, file_, name_);
  H5Handle attr(H5Acreate2(id(), name.c_str(), type.id(), space.id(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                "creating attribute " + name, file_, name_);
  const std::string bytes = text.empty() ? std::string(1, '\0') : text;
  h5Check(H5Awrite(attr.id(), type.id(), bytes.data()), "writing attribute " + name, file_, name_);
}
std::string H5Group::readAttributeString(const std::string& name) const {
  if (H5Aexists(id(), name.c_str()) <= 0)
    throw std::runtime_error("HDF5: no attribute '" + name + "' on '" + name_ + "' in file '" + file_ + "'");
  H5Handle attr(H5Aopen(id(), name.c_str(), H5P_DEFAULT), H5Aclose, "opening attribute " + name, file_, name_);
  H5Handle type(H5Aget_type(attr.id()), H5Tclose, "type of attribute " + name, file_, name_);
  if (H5Tget_class(type.id()) != H5T_STRING || H5Tis_variable_str(type.id()) > 0)
    throw std::runtime_error("HDF5: attribute '" + name + "' on '" + name_ + "' in file '" + file_ +
                             "' is not a fixed-length string");
  const std::size_t n = H5Tget_size(type.id());
  std::string s(n, '\0');
  h5Check(H5Aread(attr.id(), type.id(), s.data()), "reading attribute " + name, file_, name_);
  s.erase(std::find(s.begin(), s.end(), '\0'), s.end());
  return s;
}
bool H5Group::hasAttribute(const std::string& name) const { return H5Aexists(id(), name.c_str()) > 0; }
std::vector<double> H5Group::readAttributeDouble(const std::string& name) const {
  return readAttr<double>(id(), H5T_NATIVE_DOUBLE, name, file_, name_);
}
std::vector<std::int64_t> H5Group::readAttributeInt(const std::string& name) const {
  return readAttr<std::int64_t>(id(), H5T_NATIVE_INT64, name, file_, name_);
}

// ---- H5File ---------------------------------------------------------------------------------

H5File::H5File(hid_t id, std::string path, bool parallel)
    : H5Handle(id, H5Fclose, parallel ? "collective open" : "open", path, "/"),
      path_(std::move(path)),
      parallel_(parallel) {}

H5File H5File::create(const std::string& path) {
  return H5File(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), path, false);
}

H5File H5File::create(const Comm& comm, const std::string& path) {
  const H5PropList fapl = H5PropList::fileAccessMpio(comm);
  return H5File(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.id()), path, true);
}

namespace {
void requireFile(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw std::runtime_error("HDF5: cannot open '" + path + "': no such file");
}
}  // namespace

H5File H5File::open(const std::string& path) {
  requireFile(path);
  return H5File(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), path, false);
}

H5File H5File::open(const Comm& comm, const std::string& path) {
  requireFile(path);
  const H5PropList fapl = H5PropList::fileAccessMpio(comm);
  return H5File(H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl.id()), path, true);
}

H5Group H5File::root() const { return H5Group(H5Gopen2(id(), "/", H5P_DEFAULT), path_, "/"); }

}  // namespace mpmice::core
