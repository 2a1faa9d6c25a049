// `hexgait report` as one call: the checks of every folder the page combines, then the page
// (report/report_page.h).
#pragma once

#include "report/report_page.h"

namespace hexgait {

// Every check before any work, in this order: the folders are there and the output replaces
// none of them; the evolve run and the repertoire finished; the run, the repertoire and the
// adapt folder were made on one scene (an adapt folder's is the repertoire's it adapted, read
// from adapt.json), or InputError names the two folders. Then writes the page; returns the
// number of figures on it.
int WriteReport(const ReportOptions& options);

}  // namespace hexgait
