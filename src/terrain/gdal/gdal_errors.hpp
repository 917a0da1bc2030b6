#pragma once
// GDAL set-up shared by the GDAL sources: driver registration, and the capture of the messages
// GDAL reports, so that they end up in our errors instead of on stderr. Internal to the terrain
// library (includes GDAL headers).

#include <cpl_error.h>

#include <string>
#include <vector>

namespace trailray::terrain::gdal_detail {

// Registers GDAL's drivers, once per process (safe to call from any thread, any number of times).
void ensure_gdal_registered();

// While it lives, collects what GDAL reports on this thread instead of letting GDAL's default
// handler print it. GDAL keeps its error handler stack per thread, so concurrent captures on
// other threads neither see nor disturb each other. Nest freely; not movable (GDAL holds a
// pointer to it).
class GdalErrorCapture {
 public:
  GdalErrorCapture();
  ~GdalErrorCapture();
  GdalErrorCapture(const GdalErrorCapture&) = delete;
  GdalErrorCapture& operator=(const GdalErrorCapture&) = delete;

  // The failures reported so far joined by "; " (the warnings when there was no failure);
  // `fallback` when GDAL said nothing.
  std::string message(const std::string& fallback = "no message from GDAL") const;
  bool has_failure() const { return !failures_.empty(); }

 private:
  static void CPL_STDCALL handle(CPLErr level, CPLErrorNum number, const char* text);

  std::vector<std::string> failures_, warnings_;
};

}  // namespace trailray::terrain::gdal_detail
