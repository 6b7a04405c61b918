! J2 plasticity with linear isotropic hardening as an Abaqus/Explicit VUMAT: the law of the program's built-in
! `j2_plasticity` (physics/plasticity, voce_saturation_stress 0, no damage, no temperature) written in the
! corotational frame the VUMAT interface gives, operation for operation as the built-in does it, so that the two
! agree to round-off (tests/user_material/test_user_material.cpp).
!
!   s_trial = dev(stressOld) + 2 G dev(strainInc)              (hypoelastic, corotational: Green-Naghdi rate)
!   sigma_f = sigma_y + H eps_p (explicit hardening: eps_p at the start of the increment)
!   if sqrt(3/2 s:s) > sigma_f:  d eps_p = (sigma_eq - sigma_f) / (3 G),  s = (sigma_f / sigma_eq) s_trial
!   p = K (1 - J), J = det F (the pressure of the total volume change, as the built-in's linear EOS)
!   stressNew = s - p 1
!
! props:  E (Pa), nu, sigma_y (Pa), H (Pa)
! state:  1 equivalent plastic strain, 2 plastic work per reference volume J sigma_f d eps_p (J/m^3)
! energy: enerInternNew = enerInternOld + (stressOld + stressNew) : strainInc / (2 rho),
!         enerInelasNew = enerInelasOld + sigma_f d eps_p / rho  (per unit mass, rho the current density)
!
! Build: gfortran -shared -fPIC -O2 j2_vumat.f90 -o libj2_vumat.so   (README.md)
! Reentrant: no SAVE, no COMMON; the program calls it from several threads at once.
subroutine vumat(nblock, ndir, nshr, nstatev, nfieldv, nprops, lanneal, &
                 stepTime, totalTime, dt, cmname, coordMp, charLength, &
                 props, density, strainInc, relSpinInc, &
                 tempOld, stretchOld, defgradOld, fieldOld, &
                 stressOld, stateOld, enerInternOld, enerInelasOld, &
                 tempNew, stretchNew, defgradNew, fieldNew, &
                 stressNew, stateNew, enerInternNew, enerInelasNew)
  implicit none
  integer, intent(in) :: nblock, ndir, nshr, nstatev, nfieldv, nprops, lanneal
  real(8), intent(in) :: stepTime, totalTime, dt
  character(len=80), intent(in) :: cmname
  real(8), intent(in) :: coordMp(nblock, *), charLength(nblock), props(nprops), density(nblock)
  real(8), intent(in) :: strainInc(nblock, ndir + nshr), relSpinInc(nblock, nshr)
  real(8), intent(in) :: tempOld(nblock), tempNew(nblock), fieldOld(nblock, *), fieldNew(nblock, *)
  real(8), intent(in) :: stretchOld(nblock, ndir + nshr), stretchNew(nblock, ndir + nshr)
  real(8), intent(in) :: defgradOld(nblock, ndir + nshr + nshr), defgradNew(nblock, ndir + nshr + nshr)
  real(8), intent(in) :: stressOld(nblock, ndir + nshr), stateOld(nblock, nstatev)
  real(8), intent(in) :: enerInternOld(nblock), enerInelasOld(nblock)
  real(8), intent(inout) :: stressNew(nblock, ndir + nshr), stateNew(nblock, nstatev)
  real(8), intent(inout) :: enerInternNew(nblock), enerInelasNew(nblock)

  real(8) :: E, nu, sy, H, lambda, G, K
  real(8) :: s(6), de(6), mean, eq, sf, dep, scale, J, p, power
  integer :: i, c, ncomp

  ncomp = ndir + nshr
  E = props(1)
  nu = props(2)
  sy = props(3)
  H = props(4)
  ! the elastic constants as the program computes them (ElasticConstants::from_young_poisson)
  lambda = E * nu / ((1 + nu) * (1 - 2 * nu))
  G = E / (2 * (1 + nu))
  K = lambda + 2 * G / 3

  do i = 1, nblock
    ! trial deviator: dev(stressOld) + 2 G dev(strainInc)
    s = 0
    de = 0
    do c = 1, ncomp
      s(c) = stressOld(i, c)
      de(c) = strainInc(i, c)
    end do
    mean = (s(1) + s(2) + s(3)) * (1.0d0 / 3)
    s(1:3) = s(1:3) - mean
    mean = (de(1) + de(2) + de(3)) * (1.0d0 / 3)
    de(1:3) = de(1:3) - mean
    s = s + 2 * G * de
    ! radial return on the flow stress at the start of the increment
    eq = sqrt(1.5d0 * (s(1)**2 + s(2)**2 + s(3)**2 + 2 * (s(4)**2 + s(5)**2 + s(6)**2)))
    sf = sy + H * stateOld(i, 1)
    dep = 0
    if (eq > sf) then
      dep = (eq - sf) / (3 * G)
      scale = sf / eq
      s = s * scale
    end if
    ! pressure of the total volume change, J = det F
    if (nshr == 1) then
      J = (defgradNew(i, 1) * defgradNew(i, 2) - defgradNew(i, 4) * defgradNew(i, 5)) * defgradNew(i, 3)
    else  ! 3D: F11 F22 F33 F12 F23 F31 F21 F32 F13
      J = defgradNew(i, 1) * (defgradNew(i, 2) * defgradNew(i, 3) - defgradNew(i, 5) * defgradNew(i, 8)) &
        - defgradNew(i, 4) * (defgradNew(i, 7) * defgradNew(i, 3) - defgradNew(i, 5) * defgradNew(i, 6)) &
        + defgradNew(i, 9) * (defgradNew(i, 7) * defgradNew(i, 8) - defgradNew(i, 2) * defgradNew(i, 6))
    end if
    p = K * (1 - J)
    do c = 1, ncomp
      stressNew(i, c) = s(c)
    end do
    stressNew(i, 1:3) = stressNew(i, 1:3) - p
    stateNew(i, 1) = stateOld(i, 1) + dep
    stateNew(i, 2) = stateOld(i, 2) + J * sf * dep
    ! energies per unit mass
    power = 0
    do c = 1, ncomp
      if (c <= 3) then
        power = power + (stressOld(i, c) + stressNew(i, c)) * strainInc(i, c)
      else
        power = power + 2 * (stressOld(i, c) + stressNew(i, c)) * strainInc(i, c)
      end if
    end do
    enerInternNew(i) = enerInternOld(i) + 0.5d0 * power / density(i)
    enerInelasNew(i) = enerInelasOld(i) + sf * dep / density(i)
  end do
end subroutine vumat
