!> Restart dump and restore of the rigid-body state (model%rigid, dx_rigid_types): what the
!> rigid solver (dx_rigid_solver) carries from one cycle to the next, so a continued run
!> repeats the uninterrupted one bit for bit. Per body: centre x_c(n+1), velocity
!> vc(n+1/2), rotation R(n+1), spatial angular momentum L(n+1/2) and angular velocity, the
!> output copies x_c(n), R(n), the resultant force and torque, and the displacement each
!> prescribed motion has accumulated (VAD = 2 steers on it). System: the kinetic-energy,
!> momentum and mass corrections, the work of constraints and prescribed motion, the next
!> rbdout time and the rbdout size at the dump. Body geometry (nodes, s, mass, inertia) is
!> rebuilt from the deck. Integration: Dullweber, Leimkuhler & McLachlan 1997 (J Chem Phys
!> 107:5840); the dump file: dx_restart_file; datasets: docs/output-format.md.
module dx_rigid_restart
   use dx_kinds, only: wp
   use dx_error, only: set_error, EXIT_INPUT
   use dx_strings, only: str
   use dx_restart_file, only: rs_file_t
   use dx_rigid_types, only: rigid_system_t
   use dx_append_file, only: unit_bytes
   implicit none
   private
   public :: rigid_dump, rigid_restore

contains

   subroutine rigid_dump(rs, rig)
      type(rs_file_t), intent(inout) :: rs
      type(rigid_system_t), intent(in) :: rig
      real(wp), allocatable :: a3(:, :), a33(:, :, :)
      integer :: nb, b
      integer(8) :: bytes
      nb = size(rig%bodies)
      call rs%put('rigid_nbodies', nb)
      call rs%put('rigid_label', rig%bodies(:)%label)
      allocate(a3(3, nb), a33(3, 3, nb))
      do b = 1, nb
         a3(:, b) = rig%bodies(b)%xc
      end do
      call rs%put('rigid_xc', a3)
      do b = 1, nb
         a3(:, b) = rig%bodies(b)%vc
      end do
      call rs%put('rigid_vc', a3)
      do b = 1, nb
         a3(:, b) = rig%bodies(b)%xc_n
      end do
      call rs%put('rigid_xc_n', a3)
      do b = 1, nb
         a3(:, b) = rig%bodies(b)%lsp
      end do
      call rs%put('rigid_lsp', a3)
      do b = 1, nb
         a3(:, b) = rig%bodies(b)%omega
      end do
      call rs%put('rigid_omega', a3)
      do b = 1, nb
         a3(:, b) = rig%bodies(b)%fsum
      end do
      call rs%put('rigid_fsum', a3)
      do b = 1, nb
         a3(:, b) = rig%bodies(b)%tsum
      end do
      call rs%put('rigid_tsum', a3)
      do b = 1, nb
         a33(:, :, b) = rig%bodies(b)%rot
      end do
      call rs%put('rigid_rot', a33)
      do b = 1, nb
         a33(:, :, b) = rig%bodies(b)%rot_n
      end do
      call rs%put('rigid_rot_n', a33)
      if (nmotions(rig) > 0) call rs%put('rigid_motion_disp', motion_disp(rig))
      call rs%put('rigid_sums', [rig%ke_corr, rig%ke0_corr, rig%p_corr, rig%mass_corr, &
                                 rig%work, rig%next_rbdout])
      bytes = rig%rbdout_resume
      if (rig%rbdout_open) bytes = unit_bytes(rig%rbdout_unit)
      call rs%put('rigid_rbdout_bytes', bytes)
   end subroutine rigid_dump

   subroutine rigid_restore(rs, rig)
      type(rs_file_t), intent(inout) :: rs
      type(rigid_system_t), intent(inout) :: rig
      real(wp), allocatable :: a3(:, :), a33(:, :, :), disp(:)
      real(wp) :: sums(8)
      integer, allocatable :: labels(:)
      integer :: nb, b, k, m
      nb = -1
      call rs%get('rigid_nbodies', nb)
      if (.not. rs%ok()) return
      if (nb /= size(rig%bodies)) then
         call set_error(rs%err, 'restart file '//rs%path//' holds '//str(nb)// &
            ' rigid bodies, this deck has '//str(size(rig%bodies))// &
            ' (is it a dump of this deck?)', EXIT_INPUT)
         return
      end if
      allocate(labels(nb), a3(3, nb), a33(3, 3, nb))
      labels = 0
      call rs%get('rigid_label', labels)
      if (rs%ok()) then
         if (any(labels /= rig%bodies(:)%label)) then
            call set_error(rs%err, 'restart file '//rs%path//': its rigid bodies are '// &
               'other parts than in this deck (is it a dump of this deck?)', EXIT_INPUT)
            return
         end if
      end if
      a3 = 0.0_wp; a33 = 0.0_wp
      call rs%get('rigid_xc', a3)
      do b = 1, nb
         rig%bodies(b)%xc = a3(:, b)
      end do
      call rs%get('rigid_vc', a3)
      do b = 1, nb
         rig%bodies(b)%vc = a3(:, b)
      end do
      call rs%get('rigid_xc_n', a3)
      do b = 1, nb
         rig%bodies(b)%xc_n = a3(:, b)
      end do
      call rs%get('rigid_lsp', a3)
      do b = 1, nb
         rig%bodies(b)%lsp = a3(:, b)
      end do
      call rs%get('rigid_omega', a3)
      do b = 1, nb
         rig%bodies(b)%omega = a3(:, b)
      end do
      call rs%get('rigid_fsum', a3)
      do b = 1, nb
         rig%bodies(b)%fsum = a3(:, b)
      end do
      call rs%get('rigid_tsum', a3)
      do b = 1, nb
         rig%bodies(b)%tsum = a3(:, b)
      end do
      call rs%get('rigid_rot', a33)
      do b = 1, nb
         rig%bodies(b)%rot = a33(:, :, b)
      end do
      call rs%get('rigid_rot_n', a33)
      do b = 1, nb
         rig%bodies(b)%rot_n = a33(:, :, b)
      end do
      m = nmotions(rig)
      if (m > 0) then
         allocate(disp(m))
         disp = 0.0_wp
         call rs%get('rigid_motion_disp', disp)
         m = 0
         do b = 1, nb
            if (.not. allocated(rig%bodies(b)%motions)) cycle
            do k = 1, size(rig%bodies(b)%motions)
               m = m + 1
               rig%bodies(b)%motions(k)%disp = disp(m)
            end do
         end do
      end if
      sums = 0.0_wp
      call rs%get('rigid_sums', sums)
      rig%ke_corr = sums(1); rig%ke0_corr = sums(2); rig%p_corr = sums(3:5)
      rig%mass_corr = sums(6); rig%work = sums(7); rig%next_rbdout = sums(8)
      rig%rbdout_resume = 0
      call rs%get('rigid_rbdout_bytes', rig%rbdout_resume)
      rig%rbdout_open = .false.
   end subroutine rigid_restore

   !> prescribed motions of all bodies
   integer function nmotions(rig) result(m)
      type(rigid_system_t), intent(in) :: rig
      integer :: b
      m = 0
      do b = 1, size(rig%bodies)
         if (allocated(rig%bodies(b)%motions)) m = m + size(rig%bodies(b)%motions)
      end do
   end function nmotions

   function motion_disp(rig) result(d)
      type(rigid_system_t), intent(in) :: rig
      real(wp), allocatable :: d(:)
      integer :: b, k, m
      allocate(d(nmotions(rig)))
      m = 0
      do b = 1, size(rig%bodies)
         if (.not. allocated(rig%bodies(b)%motions)) cycle
         do k = 1, size(rig%bodies(b)%motions)
            m = m + 1
            d(m) = rig%bodies(b)%motions(k)%disp
         end do
      end do
   end function motion_disp
end module dx_rigid_restart
