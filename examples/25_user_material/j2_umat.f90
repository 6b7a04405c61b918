! J2 plasticity with linear isotropic hardening as an Abaqus/Standard UMAT: the law of the program's built-in
! `j2_plasticity` (physics/plasticity, voce_saturation_stress 0, no damage, no temperature), for the program's explicit
! schemes, which call it once per point and step with the stress of the step's start rotated by the increment's
! rotation DROT (as Abaqus does with NLGEOM) and DSTRAN = sym(L) dt in the global frame (engineering shear).
!
!   s_trial = dev(STRESS) + 2 G dev(DSTRAN)
!   sigma_f = sigma_y + H eps_p (explicit hardening);  radial return as in j2_vumat.f90
!   p = K (1 - J), J = det DFGRD1;  STRESS = s - p 1
!   DDSDDE = d STRESS / d DSTRAN of this update, the volumetric part K J 1 x 1 (F perturbed with DSTRAN)
!
! props:  E (Pa), nu, sigma_y (Pa), H (Pa)
! state:  1 equivalent plastic strain, 2 plastic work per reference volume J sigma_f d eps_p (J/m^3)
! energy: SSE = J dev(sigma):dev(sigma) / (4 G) + K (J - 1)^2 / 2, SPD += J sigma_f d eps_p (per reference volume)
!
! Build: gfortran -shared -fPIC -O2 j2_umat.f90 -o libj2_umat.so
subroutine umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, &
                stran, dstran, time, dtime, temp, dtemp, predef, dpred, cmname, &
                ndi, nshr, ntens, nstatv, props, nprops, coords, drot, pnewdt, &
                celent, dfgrd0, dfgrd1, noel, npt, layer, kspt, kstep, kinc)
  implicit none
  integer, intent(in) :: ndi, nshr, ntens, nstatv, nprops, noel, npt, layer, kspt, kstep, kinc
  character(len=80), intent(in) :: cmname
  real(8), intent(inout) :: stress(ntens), statev(nstatv), ddsdde(ntens, ntens), sse, spd, scd, rpl
  real(8), intent(inout) :: ddsddt(ntens), drplde(ntens), drpldt, pnewdt
  real(8), intent(in) :: stran(ntens), dstran(ntens), time(2), dtime, temp, dtemp, predef(*), dpred(*)
  real(8), intent(in) :: props(nprops), coords(3), drot(3, 3), celent, dfgrd0(3, 3), dfgrd1(3, 3)

  real(8) :: E, nu, sy, H, lambda, G, K
  real(8) :: s(6), de(6), mean, eq, sf, dep, scale, J, p, factor
  integer :: a, b

  E = props(1)
  nu = props(2)
  sy = props(3)
  H = props(4)
  lambda = E * nu / ((1 + nu) * (1 - 2 * nu))
  G = E / (2 * (1 + nu))
  K = lambda + 2 * G / 3

  s = 0
  de = 0
  s(1:ntens) = stress(1:ntens)
  de(1:3) = dstran(1:3)
  de(4:ntens) = 0.5d0 * dstran(4:ntens)  ! engineering shear -> tensor
  mean = (s(1) + s(2) + s(3)) * (1.0d0 / 3)
  s(1:3) = s(1:3) - mean
  mean = (de(1) + de(2) + de(3)) * (1.0d0 / 3)
  de(1:3) = de(1:3) - mean
  s = s + 2 * G * de
  eq = sqrt(1.5d0 * (s(1)**2 + s(2)**2 + s(3)**2 + 2 * (s(4)**2 + s(5)**2 + s(6)**2)))
  sf = sy + H * statev(1)
  dep = 0
  scale = 1
  if (eq > sf) then
    dep = (eq - sf) / (3 * G)
    scale = sf / eq
    s = s * scale
  end if
  J = dfgrd1(1, 1) * (dfgrd1(2, 2) * dfgrd1(3, 3) - dfgrd1(2, 3) * dfgrd1(3, 2)) &
    - dfgrd1(1, 2) * (dfgrd1(2, 1) * dfgrd1(3, 3) - dfgrd1(2, 3) * dfgrd1(3, 1)) &
    + dfgrd1(1, 3) * (dfgrd1(2, 1) * dfgrd1(3, 2) - dfgrd1(2, 2) * dfgrd1(3, 1))
  p = K * (1 - J)
  stress(1:ntens) = s(1:ntens)
  stress(1:3) = stress(1:3) - p

  ! tangent: d s = scale 2 G [dev(d eps) - 3/2 s_tr (s_tr : d eps) / eq^2] (s_tr = s / scale), + K J 1 x 1
  ddsdde = 0
  do a = 1, ntens
    do b = 1, ntens
      if (a <= 3 .and. b <= 3) then
        ddsdde(a, b) = -scale * 2 * G / 3 + K * J
        if (a == b) ddsdde(a, b) = ddsdde(a, b) + scale * 2 * G
      else if (a == b) then
        ddsdde(a, b) = scale * G
      end if
    end do
  end do
  if (dep > 0) then
    factor = scale * 2 * G * 1.5d0 / (eq * eq * scale * scale)
    do a = 1, ntens
      do b = 1, ntens
        ddsdde(a, b) = ddsdde(a, b) - factor * s(a) * s(b)
      end do
    end do
  end if

  sse = J * (s(1)**2 + s(2)**2 + s(3)**2 + 2 * (s(4)**2 + s(5)**2 + s(6)**2)) / (4 * G) + 0.5d0 * K * (J - 1)**2
  spd = spd + J * sf * dep
  statev(1) = statev(1) + dep
  statev(2) = statev(2) + J * sf * dep
end subroutine umat
