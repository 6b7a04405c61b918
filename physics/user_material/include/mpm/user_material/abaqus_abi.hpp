#pragma once
/// \file abaqus_abi.hpp
/// The Fortran calling convention of Abaqus' VUMAT and UMAT as gfortran (and ifx/ifort on Linux) compile them:
/// every argument by reference, INTEGER as a 4-byte int, REAL*8 as double, CHARACTER*80 CMNAME as a pointer to 80
/// characters (blank-padded, not 0-terminated) with its length appended after the last argument as a size_t (the
/// hidden length of gfortran >= 8). Arrays are Fortran's: column-major, so VUMAT's stressOld(nblock, ncomp) holds
/// component c of point i at i + c * nblock, and UMAT's DFGRD0(3, 3) holds F_ij at (i - 1) + 3 (j - 1).

#include <cstddef>

namespace mpm::user_material {

/// CHARACTER*80 of CMNAME.
inline constexpr std::size_t cmname_length = 80;

extern "C" {
/// SUBROUTINE VUMAT(nblock, ndir, nshr, nstatev, nfieldv, nprops, lanneal, stepTime, totalTime, dt, cmname, coordMp,
///   charLength, props, density, strainInc, relSpinInc, tempOld, stretchOld, defgradOld, fieldOld, stressOld,
///   stateOld, enerInternOld, enerInelasOld, tempNew, stretchNew, defgradNew, fieldNew, stressNew, stateNew,
///   enerInternNew, enerInelasNew)
using VumatFunction = void (*)(const int* nblock, const int* ndir, const int* nshr, const int* nstatev,
                               const int* nfieldv, const int* nprops, const int* lanneal, const double* step_time,
                               const double* total_time, const double* dt, const char* cmname, const double* coord_mp,
                               const double* char_length, const double* props, const double* density,
                               const double* strain_inc, const double* rel_spin_inc, const double* temp_old,
                               const double* stretch_old, const double* defgrad_old, const double* field_old,
                               const double* stress_old, const double* state_old, const double* ener_intern_old,
                               const double* ener_inelas_old, const double* temp_new, const double* stretch_new,
                               const double* defgrad_new, const double* field_new, double* stress_new,
                               double* state_new, double* ener_intern_new, double* ener_inelas_new,
                               std::size_t cmname_len);

/// SUBROUTINE UMAT(STRESS, STATEV, DDSDDE, SSE, SPD, SCD, RPL, DDSDDT, DRPLDE, DRPLDT, STRAN, DSTRAN, TIME, DTIME,
///   TEMP, DTEMP, PREDEF, DPRED, CMNAME, NDI, NSHR, NTENS, NSTATV, PROPS, NPROPS, COORDS, DROT, PNEWDT, CELENT,
///   DFGRD0, DFGRD1, NOEL, NPT, LAYER, KSPT, KSTEP, KINC)
using UmatFunction = void (*)(double* stress, double* statev, double* ddsdde, double* sse, double* spd, double* scd,
                              double* rpl, double* ddsddt, double* drplde, double* drpldt, const double* stran,
                              const double* dstran, const double* time, const double* dtime, const double* temp,
                              const double* dtemp, const double* predef, const double* dpred, const char* cmname,
                              const int* ndi, const int* nshr, const int* ntens, const int* nstatv, const double* props,
                              const int* nprops, const double* coords, const double* drot, double* pnewdt,
                              const double* celent, const double* dfgrd0, const double* dfgrd1, const int* noel,
                              const int* npt, const int* layer, const int* kspt, const int* kstep, const int* kinc,
                              std::size_t cmname_len);
}

}  // namespace mpm::user_material
