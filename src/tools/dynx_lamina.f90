!> dynx-lamina: the plane-stress lamina studies (docs/studies/lamina.md).
!>   dynx-lamina maps DIR      iso-error maps of the one-step (4 and its entry-normal variant 5),
!>                             secant (1) and radial (3) returns against the full return (2):
!>                             DIR/lamina_map_<state>_<alg>.dat (theta deg, log10 size, log10 error)
!>                             and DIR/lamina_map_summary.dat (largest error per size)
!>   dynx-lamina bench [REPS]  ns per lamina update of each algorithm on chunks of 128 points
!> The material: *MAT_PLASTIC_KINEMATIC E = 200 GPa, nu = 0.3, sigma_y = 250 MPa, Et = 2 GPa
!> (physics-references.md 3.1), BETA = 1 for the maps (isotropic), 0.5 for the benchmark.
!> Map method: Krieg & Krieg 1977 (see dx_lamina).
program dynx_lamina
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, int64
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_mat_plastic_kinematic, only: mat_plastic_kinematic_t
   use dx_plane_stress, only: PS_SECANT3, PS_FULL, PS_RADIAL, PS_ONE_STEP, PS_ONE_STEP_N, &
                              ps_alg_name
   use dx_lamina, only: lamina_map_point
   implicit none
   character(256) :: mode, arg
   type(mat_plastic_kinematic_t) :: pk
   type(error_t), allocatable :: err
   real(wp), parameter :: sy = 250.0_wp
   integer :: reps, ios

   pk%ro = 7.8e-9_wp; pk%e = 200.0e3_wp; pk%pr = 0.3_wp; pk%sigy = sy; pk%etan = 2000.0_wp
   pk%beta = 1.0_wp
   call pk%setup(err)
   if (allocated(err)) error stop 'dynx-lamina: material setup failed'
   if (command_argument_count() < 1) then
      write(error_unit, '(a)') 'usage: dynx-lamina maps DIR | dynx-lamina bench [REPS]'
      stop 2
   end if
   call get_command_argument(1, mode)
   select case (trim(mode))
   case ('maps')
      arg = 'docs/studies/data'
      if (command_argument_count() >= 2) call get_command_argument(2, arg)
      call maps(trim(arg))
   case ('bench')
      reps = 20000
      if (command_argument_count() >= 2) then
         call get_command_argument(2, arg)
         read(arg, *, iostat=ios) reps
         if (ios /= 0 .or. reps < 1) then
            write(error_unit, '(a)') 'dynx-lamina: bench REPS must be a positive integer, got '// &
               trim(arg)
            stop 2
         end if
      end if
      pk%beta = 0.5_wp
      call pk%setup(err)
      call bench(reps)
   case default
      write(error_unit, '(a)') 'dynx-lamina: unknown mode '//trim(mode)//' (maps or bench)'
      stop 2
   end select

contains

   subroutine maps(dir)
      character(*), intent(in) :: dir
      integer, parameter :: algs(4) = [PS_ONE_STEP, PS_ONE_STEP_N, PS_SECANT3, PS_RADIAL]
      character(*), parameter :: anames(4) = [character(8) :: 'onestep', 'onestepn', 'secant3', &
                                                                'radial']
      character(*), parameter :: snames(2) = [character(8) :: 'uniaxial', 'shear']
      real(wp) :: sig0(5), hv0(7), th, lsz, sz, e1, ep, worst(4, 2, 5)
      integer :: ist, ia, it, is, u, us, k
      worst = 0.0_wp
      do ist = 1, 2
         sig0 = 0.0_wp; hv0 = 0.0_wp
         if (ist == 1) then
            sig0(1) = sy
         else
            sig0(1) = sy/sqrt(3.0_wp); sig0(2) = -sy/sqrt(3.0_wp)
         end if
         do ia = 1, 4
            open(newunit=u, file=dir//'/lamina_map_'//trim(snames(ist))//'_'//trim(anames(ia))// &
                 '.dat', status='replace', action='write')
            write(u, '(a)') '# '//ps_alg_name(algs(ia))//' against the full return, start '// &
               trim(snames(ist))//' yield state; E 200e3 nu 0.3 sy 250 Et 2000 beta 1'
            write(u, '(a)') '# theta_deg log10_size log10(|dsig|_vM/sigma_y)'
            do it = 0, 72
               th = 5.0_wp*it
               do is = 0, 40
                  lsz = -6.0_wp + 0.1_wp*is
                  sz = 10.0_wp**lsz
                  call lamina_map_point(pk, algs(ia), sig0, hv0, &
                     sz*[cos(th*acos(-1.0_wp)/180.0_wp), sin(th*acos(-1.0_wp)/180.0_wp), 0.0_wp, &
                     0.0_wp, 0.0_wp], sy, e1, ep)
                  write(u, '(f6.1,f6.2,f9.3)') th, lsz, log10(max(e1, 1.0e-17_wp))
                  if (mod(is, 10) == 0) then
                     k = is/10 + 1
                     worst(ia, ist, k) = max(worst(ia, ist, k), e1)
                  end if
               end do
               write(u, '(a)') ''
            end do
            close(u)
         end do
      end do
      open(newunit=us, file=dir//'/lamina_map_summary.dat', status='replace', action='write')
      write(us, '(a)') '# largest |dsig|_vM/sigma_y over the 73 directions, by increment size'
      write(us, '(a)') '# state algorithm 1e-6 1e-5 1e-4 1e-3 1e-2'
      do ist = 1, 2
         do ia = 1, 4
            write(us, '(a10,a10,5es10.2)') trim(snames(ist)), trim(anames(ia)), worst(ia, ist, :)
         end do
      end do
      close(us)
      write(output_unit, '(a)') 'dynx-lamina: maps written to '//dir
   end subroutine maps

   !> ns per point update: nv = 128 points on the yield surface (mixed-hardening prestrain) get
   !> plastic increments of size 1e-4 in varied directions (all points plastic), and the same with
   !> every other point unloading; each repetition restarts from the same state.
   subroutine bench(reps)
      integer, intent(in) :: reps
      integer, parameter :: nv = 128
      integer, parameter :: algs(5) = [PS_SECANT3, PS_ONE_STEP, PS_RADIAL, PS_ONE_STEP_N, PS_FULL]
      real(wp) :: sig0(nv, 5), hv0(nv, 7), sig(nv, 5), hv(nv, 7), de(nv, 5), th, t(5, 2), chk
      integer :: ierr(nv), i, ia, r, mix
      integer(int64) :: c0, c1, rate
      do i = 1, nv
         th = 2.0_wp*acos(-1.0_wp)*(i - 1)/nv
         sig0(i, :) = [sy*cos(th), sy*sin(th)*0.5_wp, 0.3_wp*sy*sin(2.0_wp*th), 0.0_wp, 0.0_wp]
         ! onto the yield surface of the virgin material
         sig0(i, 1:3) = sig0(i, 1:3)*sy/sqrt(sig0(i, 1)**2 + sig0(i, 2)**2 - sig0(i, 1)*sig0(i, 2) + &
                                             3.0_wp*sig0(i, 3)**2)
      end do
      hv0 = 0.0_wp
      chk = 0.0_wp
      do mix = 1, 2
         do i = 1, nv
            ! outward: along the stress direction plus a rotating tangential part
            de(i, 1:3) = 1.0e-4_wp*(sig0(i, 1:3)/sy + 0.5_wp*[sin(0.1_wp*i), cos(0.1_wp*i), &
                                                              0.2_wp*sin(0.3_wp*i)])
            de(i, 4:5) = 1.0e-5_wp
            if (mix == 2 .and. mod(i, 2) == 0) de(i, 1:3) = -de(i, 1:3)
         end do
         do ia = 1, 5
            pk%ps_alg = algs(ia)
            call system_clock(c0, rate)
            do r = 1, reps
               sig = sig0; hv = hv0; ierr = 0
               call pk%update_plane_stress(nv, 1.0e-6_wp, de, sig, hv, ierr)
               chk = chk + sig(1 + mod(r, nv), 1)
            end do
            call system_clock(c1)
            t(ia, mix) = real(c1 - c0, wp)/real(rate, wp)*1.0e9_wp/(real(reps, wp)*nv)
         end do
      end do
      ! the copy of the state (sig = sig0; hv = hv0) is inside the timing: time it alone
      call system_clock(c0, rate)
      do r = 1, reps
         sig = sig0; hv = hv0
         chk = chk + sig(1 + mod(r, nv), 1) + hv(1 + mod(r, nv), 1)
      end do
      call system_clock(c1)
      th = real(c1 - c0, wp)/real(rate, wp)*1.0e9_wp/(real(reps, wp)*nv)
      write(output_unit, '(a,i0,a,i0,a)') '# ns per lamina update (nv = ', nv, ', ', reps, &
         ' repetitions, state copy subtracted); checksum follows'
      write(output_unit, '(a)') '# algorithm                                   all plastic   half unloading'
      do ia = 1, 5
         write(output_unit, '(a46,2f12.2)') ps_alg_name(algs(ia)), t(ia, 1) - th, t(ia, 2) - th
      end do
      write(output_unit, '(a,f8.1,a,f8.1,a)') '# one-step saving against secant x3: ', &
         100.0_wp*(1.0_wp - (t(2, 1) - th)/(t(1, 1) - th)), ' % (all plastic), ', &
         100.0_wp*(1.0_wp - (t(2, 2) - th)/(t(1, 2) - th)), ' % (half unloading)'
      write(output_unit, '(a,es12.4,a,f6.2)') '# checksum ', chk, '  copy ns ', th
   end subroutine bench
end program dynx_lamina
