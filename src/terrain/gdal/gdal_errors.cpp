#include "terrain/gdal/gdal_errors.hpp"

#include <gdal.h>

#include <mutex>

namespace trailray::terrain::gdal_detail {

void ensure_gdal_registered() {
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
}

GdalErrorCapture::GdalErrorCapture() { CPLPushErrorHandlerEx(&GdalErrorCapture::handle, this); }

GdalErrorCapture::~GdalErrorCapture() { CPLPopErrorHandler(); }

void CPL_STDCALL GdalErrorCapture::handle(CPLErr level, CPLErrorNum /*number*/, const char* text) {
  auto* self = static_cast<GdalErrorCapture*>(CPLGetErrorHandlerUserData());
  if (self == nullptr || text == nullptr) return;
  // Debug output (CPL_DEBUG) is for GDAL's developers; it is neither kept nor printed.
  if (level == CE_Failure || level == CE_Fatal) {
    self->failures_.emplace_back(text);
  } else if (level == CE_Warning) {
    self->warnings_.emplace_back(text);
  }
}

std::string GdalErrorCapture::message(const std::string& fallback) const {
  const std::vector<std::string>& parts = failures_.empty() ? warnings_ : failures_;
  if (parts.empty()) return fallback;
  std::string joined;
  for (const std::string& part : parts) {
    if (!joined.empty()) joined += "; ";
    joined += part;
  }
  return joined;
}

}  // namespace trailray::terrain::gdal_detail
