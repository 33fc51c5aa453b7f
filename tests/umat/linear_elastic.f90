! Linear isotropic elasticity as an Abaqus UMAT (Hooke's law in increments):
!   STRESS <- STRESS + D DSTRAN,  D = lambda 1(x)1 + 2 mu I (engineering shears: D(4,4) = mu).
! PROPS(1) = E (the UMAT's stress unit), PROPS(2) = nu. No state variables.
subroutine umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, &
                time, dtime, temp, dtemp, predef, dpred, cmname, ndi, nshr, ntens, nstatv, props, nprops, &
                coords, drot, pnewdt, celent, dfgrd0, dfgrd1, noel, npt, layer, kspt, kstep, kinc)
  implicit none
  character(len=80), intent(in) :: cmname
  integer, intent(in) :: ndi, nshr, ntens, nstatv, nprops, noel, npt, layer, kspt, kinc
  integer, intent(in) :: kstep(4)
  double precision, intent(inout) :: stress(ntens), statev(*), sse, spd, scd, rpl, drpldt, pnewdt
  double precision, intent(out) :: ddsdde(ntens, ntens), ddsddt(ntens), drplde(ntens)
  double precision, intent(in) :: stran(ntens), dstran(ntens), time(2), dtime, temp, dtemp, predef(*), dpred(*)
  double precision, intent(in) :: props(nprops), coords(3), drot(3, 3), celent, dfgrd0(3, 3), dfgrd1(3, 3)
  double precision :: young, nu, lambda, mu
  integer :: i, j

  young = props(1)
  nu = props(2)
  lambda = young*nu/((1d0 + nu)*(1d0 - 2d0*nu))
  mu = young/(2d0*(1d0 + nu))
  ddsdde = 0d0
  do i = 1, ndi
    do j = 1, ndi
      ddsdde(i, j) = lambda
    end do
    ddsdde(i, i) = lambda + 2d0*mu
  end do
  do i = ndi + 1, ntens
    ddsdde(i, i) = mu
  end do
  stress = stress + matmul(ddsdde, dstran)
end subroutine umat
