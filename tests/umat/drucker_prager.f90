! Drucker-Prager elastic-perfectly-plastic UMAT with non-associated flow, written independently of
! soilsph's C++ model to the same equations (docs/method: paper eq 17-20, "matched" potential):
!   f = sqrt(J2) + a_phi I1 - k_c,  g = sqrt(J2) + a_psi I1,
!   a_phi = tan(phi)/sqrt(9 + 12 tan^2 phi), k_c = 3c/sqrt(9 + 12 tan^2 phi), a_psi likewise with psi.
! Closed-form return (elasticity constant): dlambda = f_trial/(G + 9 K a_phi a_psi), the deviator
! scaled by 1 - G dlambda/sqrt(J2_trial), I1 reduced by 9 K a_psi dlambda; past the apex the stress
! returns to the apex I1 = k_c/a_phi. DDSDDE is the consistent tangent of this return (de Souza Neto,
! Peric & Owen 2008, sec. 8.3.1, written for sqrt(J2)):
!   D_ep = 2G(1 - G dl/J)(I_dev - n(x)n) + 2G n(x)n + K 1(x)1 - (sqrt2 G n + 3K a_psi 1)(x)(sqrt2 G n + 3K a_phi 1)/A
! with n = s_trial/|s_trial|, J = sqrt(J2_trial), A = G + 9 K a_phi a_psi; zero at the apex.
! PROPS = E, nu, phi (degrees), c, psi (degrees). STATEV(1) = accumulated plastic multiplier.
subroutine umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, &
                time, dtime, temp, dtemp, predef, dpred, cmname, ndi, nshr, ntens, nstatv, props, nprops, &
                coords, drot, pnewdt, celent, dfgrd0, dfgrd1, noel, npt, layer, kspt, kstep, kinc)
  implicit none
  character(len=80), intent(in) :: cmname
  integer, intent(in) :: ndi, nshr, ntens, nstatv, nprops, noel, npt, layer, kspt, kinc
  integer, intent(in) :: kstep(4)
  double precision, intent(inout) :: stress(ntens), statev(nstatv), sse, spd, scd, rpl, drpldt, pnewdt
  double precision, intent(out) :: ddsdde(ntens, ntens), ddsddt(ntens), drplde(ntens)
  double precision, intent(in) :: stran(ntens), dstran(ntens), time(2), dtime, temp, dtemp, predef(*), dpred(*)
  double precision, intent(in) :: props(nprops), coords(3), drot(3, 3), celent, dfgrd0(3, 3), dfgrd1(3, 3)
  double precision, parameter :: pi = 3.14159265358979323846d0
  double precision :: young, nu, bulk, shear, a_phi, a_psi, k_c, t_phi, t_psi
  double precision :: de(6, 6), trial(6), s(6), n(6), one(6), a(6), b(6)
  double precision :: i1, j, f, dl, big_a, norm_s
  integer :: i, k

  young = props(1)
  nu = props(2)
  t_phi = tan(props(3)*pi/180d0)
  t_psi = tan(props(5)*pi/180d0)
  a_phi = t_phi/sqrt(9d0 + 12d0*t_phi**2)
  a_psi = t_psi/sqrt(9d0 + 12d0*t_psi**2)
  k_c = 3d0*props(4)/sqrt(9d0 + 12d0*t_phi**2)
  bulk = young/(3d0*(1d0 - 2d0*nu))
  shear = young/(2d0*(1d0 + nu))
  one = (/1d0, 1d0, 1d0, 0d0, 0d0, 0d0/)

  de = 0d0
  do i = 1, 3
    do k = 1, 3
      de(i, k) = bulk - 2d0*shear/3d0
    end do
    de(i, i) = bulk + 4d0*shear/3d0
    de(i + 3, i + 3) = shear
  end do

  trial = stress + matmul(de, dstran)
  i1 = trial(1) + trial(2) + trial(3)
  s = trial - i1/3d0*one
  ! |s|^2 with the tensor's shear components counted twice (Voigt stress holds sigma_12 once)
  norm_s = sqrt(s(1)**2 + s(2)**2 + s(3)**2 + 2d0*(s(4)**2 + s(5)**2 + s(6)**2))
  j = norm_s/sqrt(2d0)
  f = j + a_phi*i1 - k_c
  ddsdde = de
  if (f <= 0d0) then
    stress = trial
    return
  end if

  big_a = shear + 9d0*bulk*a_phi*a_psi
  dl = f/big_a
  if (j - shear*dl >= 0d0) then  ! cone
    stress = s*(1d0 - shear*dl/j) + (i1 - 9d0*bulk*a_psi*dl)/3d0*one
    n = s/norm_s
    a = sqrt(2d0)*shear*n + 3d0*bulk*a_psi*one
    b = sqrt(2d0)*shear*n + 3d0*bulk*a_phi*one
    ! (c (x) d) : d_eps in Voigt form is c_i d_k dstran_k with d's plain components: an engineering
    ! shear strain is twice the tensor's, and the tensor sum counts the shear pair twice.
    ddsdde = 0d0
    do i = 1, 6
      do k = 1, 6
        ddsdde(i, k) = bulk*one(i)*one(k) + 2d0*shear*(shear*dl/j)*n(i)*n(k) - a(i)*b(k)/big_a
      end do
    end do
    do i = 1, 3
      do k = 1, 3
        ddsdde(i, k) = ddsdde(i, k) - 2d0*shear*(1d0 - shear*dl/j)/3d0
      end do
      ddsdde(i, i) = ddsdde(i, i) + 2d0*shear*(1d0 - shear*dl/j)
      ddsdde(i + 3, i + 3) = ddsdde(i + 3, i + 3) + shear*(1d0 - shear*dl/j)
    end do
  else  ! apex
    dl = (i1 - k_c/a_phi)/(9d0*bulk*a_psi)
    stress = k_c/a_phi/3d0*one
    ddsdde = 0d0
  end if
  if (nstatv >= 1) statev(1) = statev(1) + dl
end subroutine umat
