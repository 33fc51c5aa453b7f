/* A UMAT in C with its entry point renamed (umat_elastic_c), for the adapter's tests: linear
 * elasticity (PROPS = E, nu), and, chosen by CMNAME, the faults a plug-in can have once it is past
 * the probe call (zero strain increment):
 *   ELASTIC        Hooke's law in increments
 *   HALVES         Hooke's law, but PNEWDT = 0.5 for any strain increment larger than 1e-4 (max norm)
 *   PNEWDT         PNEWDT = 0.5 for every non-zero strain increment
 *   NAN-STRESS     a NaN stress for every non-zero strain increment
 *   ZERO-TANGENT   Hooke's law with DDSDDE = 0 for every non-zero strain increment
 *   ONE-AT-A-TIME  Hooke's law, each call held open for 20 microseconds; a NaN stress when another
 *                  call is in progress: a UMAT with SAVE variables, called from two threads at once
 *   SEGFAULT       a write through a null pointer for every non-zero strain increment
 *   ABORT          abort() for every non-zero strain increment
 *   STOP           exit(0), as Fortran's STOP does, for every non-zero strain increment
 * It declares its PROPS length (soilsph_umat_nprops): 2 for each of these names. */
#include <math.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static int named(const char* cmname, size_t length, const char* name) {
  const size_t n = strlen(name);
  if (length < n || memcmp(cmname, name, n) != 0) return 0;
  for (size_t k = n; k < length; ++k)
    if (cmname[k] != ' ') return 0;
  return 1;
}

int soilsph_umat_nprops(const char* cmname, size_t length) {
  const char* names[] = {"ELASTIC",  "HALVES", "PNEWDT", "NAN-STRESS",   "ZERO-TANGENT",
                         "SEGFAULT", "ABORT",  "STOP",   "ONE-AT-A-TIME"};
  for (size_t k = 0; k < sizeof names / sizeof *names; ++k)
    if (named(cmname, length, names[k])) return 2;
  return -1;
}

void umat_elastic_c(double* stress, double* statev, double* ddsdde, double* sse, double* spd, double* scd,
                    double* rpl, double* ddsddt, double* drplde, double* drpldt, const double* stran,
                    const double* dstran, const double* time, const double* dtime, const double* temp,
                    const double* dtemp, const double* predef, const double* dpred, const char* cmname,
                    const int* ndi, const int* nshr, const int* ntens, const int* nstatv, const double* props,
                    const int* nprops, const double* coords, const double* drot, double* pnewdt,
                    const double* celent, const double* dfgrd0, const double* dfgrd1, const int* noel,
                    const int* npt, const int* layer, const int* kspt, const int* kstep, const int* kinc,
                    size_t cmname_length) {
  static atomic_int calls_in_progress = 0;
  if (named(cmname, cmname_length, "ONE-AT-A-TIME")) {
    const int others = atomic_fetch_add(&calls_in_progress, 1);
    const struct timespec held = {0, 20000};
    nanosleep(&held, NULL);
    atomic_fetch_sub(&calls_in_progress, 1);
    if (others > 0) {
      for (int k = 0; k < *ntens; ++k) stress[k] = NAN;
      return;
    }
  }
  const int n = *ntens;
  const double young = props[0], nu = props[1];
  const double lambda = young * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), mu = young / (2.0 * (1.0 + nu));
  double largest = 0.0;
  for (int k = 0; k < n; ++k) largest = fmax(largest, fabs(dstran[k]));
  for (int k = 0; k < n * n; ++k) ddsdde[k] = 0.0;
  for (int i = 0; i < *ndi; ++i) {
    for (int j = 0; j < *ndi; ++j) ddsdde[i + n * j] = lambda;
    ddsdde[i + n * i] = lambda + 2.0 * mu;
  }
  for (int i = *ndi; i < n; ++i) ddsdde[i + n * i] = mu;

  if (largest > 0.0 && (named(cmname, cmname_length, "PNEWDT") ||
                        (named(cmname, cmname_length, "HALVES") && largest > 1e-4))) {
    *pnewdt = 0.5;
    return;
  }
  if (largest > 0.0 && named(cmname, cmname_length, "SEGFAULT")) {
    int* volatile nowhere = NULL;
    *nowhere = 1;
  }
  if (largest > 0.0 && named(cmname, cmname_length, "ABORT")) abort();
  if (largest > 0.0 && named(cmname, cmname_length, "STOP")) exit(0);
  if (largest > 0.0 && named(cmname, cmname_length, "NAN-STRESS")) {
    for (int k = 0; k < n; ++k) stress[k] = NAN;
    return;
  }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) stress[i] += ddsdde[i + n * j] * dstran[j];
  if (largest > 0.0 && named(cmname, cmname_length, "ZERO-TANGENT"))
    for (int k = 0; k < n * n; ++k) ddsdde[k] = 0.0;
}
