! A Fortran programme calling libsoilsph_umat.so's umat_ as a finite-element code would: one small
! increment of Drucker-Prager (E = 1 MPa, nu = 0.3, phi = 35, c = 0, psi = 0) from an isotropic
! 100 kPa, which stays inside the cone, so Hooke's law gives the answer:
!   d_sigma_11 = (K + 4G/3) d_eps_11,  d_sigma_22 = (K - 2G/3) d_eps_11,  and DDSDDE(1,1) = K + 4G/3.
! Exits with status 1 if either differs by more than 1e-12 relative.
program call_from_fortran
  implicit none
  double precision :: stress(6), statev(4), ddsdde(6, 6), sse, spd, scd, rpl, ddsddt(6), drplde(6), drpldt
  double precision :: stran(6), dstran(6), time(2), dtime, temp, dtemp, predef(1), dpred(1), props(5)
  double precision :: coords(3), drot(3, 3), pnewdt, celent, dfgrd0(3, 3), dfgrd1(3, 3)
  double precision :: bulk, shear, d11, d21
  character(len=80) :: cmname
  integer :: kstep(4)

  stress = (/-1d5, -1d5, -1d5, 0d0, 0d0, 0d0/)
  statev = 0d0
  stran = 0d0
  dstran = (/-1d-4, 0d0, 0d0, 0d0, 0d0, 0d0/)
  props = (/1d6, 0.3d0, 35d0, 0d0, 0d0/)
  cmname = 'DRUCKER-PRAGER'
  time = 0d0
  dtime = 1d0
  temp = 0d0
  dtemp = 0d0
  predef = 0d0
  dpred = 0d0
  coords = 0d0
  drot = 0d0
  drot(1, 1) = 1d0
  drot(2, 2) = 1d0
  drot(3, 3) = 1d0
  dfgrd0 = drot
  dfgrd1 = drot
  pnewdt = 1d36
  celent = 1d0
  kstep = (/1, 1, 0, 0/)
  call umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, time, dtime, &
            temp, dtemp, predef, dpred, cmname, 3, 3, 6, 4, props, 5, coords, drot, pnewdt, celent, dfgrd0, &
            dfgrd1, 1, 1, 1, 1, kstep, 1)

  bulk = 1d6/(3d0*(1d0 - 0.6d0))
  shear = 1d6/(2d0*1.3d0)
  d11 = (bulk + 4d0*shear/3d0)*dstran(1)
  d21 = (bulk - 2d0*shear/3d0)*dstran(1)
  print '(a, 2es24.16)', 'stress 11, 22: ', stress(1), stress(2)
  if (pnewdt < 1d0) stop 1
  if (abs(stress(1) - (-1d5 + d11)) > 1d-12*1d5 .or. abs(stress(2) - (-1d5 + d21)) > 1d-12*1d5) stop 1
  if (abs(ddsdde(1, 1) - (bulk + 4d0*shear/3d0)) > 1d-12*bulk) stop 1
end program call_from_fortran
