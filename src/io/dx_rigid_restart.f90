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
   use dx_rigid_types, only: rigid_system_t, rigid_body_t
   use dx_append_file, only: unit_bytes
   implicit none
   private
   public :: rigid_dump, rigid_restore

   !> The per-body vectors and matrices of the dump, in dump order (datasets rigid_<name>).
   character(*), parameter :: VEC_NAMES(7) = [character(5) :: 'xc', 'vc', 'xc_n', 'lsp', &
                                              'omega', 'fsum', 'tsum']
   character(*), parameter :: MAT_NAMES(2) = [character(5) :: 'rot', 'rot_n']

contains

   !> The body's vector VEC_NAMES(k).
   function vec_of(body, k) result(p)
      type(rigid_body_t), target :: body
      integer, intent(in) :: k
      real(wp), pointer :: p(:)
      select case (k)
      case (1); p => body%xc
      case (2); p => body%vc
      case (3); p => body%xc_n
      case (4); p => body%lsp
      case (5); p => body%omega
      case (6); p => body%fsum
      case default; p => body%tsum
      end select
   end function vec_of

   !> The body's matrix MAT_NAMES(k).
   function mat_of(body, k) result(q)
      type(rigid_body_t), target :: body
      integer, intent(in) :: k
      real(wp), pointer :: q(:, :)
      if (k == 1) then
         q => body%rot
      else
         q => body%rot_n
      end if
   end function mat_of

   subroutine rigid_dump(rs, rig)
      type(rs_file_t), intent(inout) :: rs
      type(rigid_system_t), intent(in), target :: rig
      real(wp), allocatable :: a3(:, :), a33(:, :, :)
      real(wp), pointer :: p(:), q(:, :)
      integer :: nb, b, k
      integer(8) :: bytes
      nb = size(rig%bodies)
      call rs%put('rigid_nbodies', nb)
      call rs%put('rigid_label', rig%bodies(:)%label)
      allocate(a3(3, nb), a33(3, 3, nb))
      do k = 1, size(VEC_NAMES)
         do b = 1, nb
            p => vec_of(rig%bodies(b), k)
            a3(:, b) = p
         end do
         call rs%put('rigid_'//trim(VEC_NAMES(k)), a3)
      end do
      do k = 1, size(MAT_NAMES)
         do b = 1, nb
            q => mat_of(rig%bodies(b), k)
            a33(:, :, b) = q
         end do
         call rs%put('rigid_'//trim(MAT_NAMES(k)), a33)
      end do
      if (nmotions(rig) > 0) call rs%put('rigid_motion_disp', motion_disp(rig))
      call rs%put('rigid_sums', [rig%ke_corr, rig%ke0_corr, rig%p_corr, rig%mass_corr, &
                                 rig%work, rig%next_rbdout])
      bytes = rig%rbdout_resume
      if (rig%rbdout_open) bytes = unit_bytes(rig%rbdout_unit)
      call rs%put('rigid_rbdout_bytes', bytes)
   end subroutine rigid_dump

   subroutine rigid_restore(rs, rig)
      type(rs_file_t), intent(inout) :: rs
      type(rigid_system_t), intent(inout), target :: rig
      real(wp), allocatable :: a3(:, :), a33(:, :, :), disp(:)
      real(wp), pointer :: p(:), q(:, :)
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
      do k = 1, size(VEC_NAMES)
         call rs%get('rigid_'//trim(VEC_NAMES(k)), a3)
         do b = 1, nb
            p => vec_of(rig%bodies(b), k)
            p = a3(:, b)
         end do
      end do
      do k = 1, size(MAT_NAMES)
         call rs%get('rigid_'//trim(MAT_NAMES(k)), a33)
         do b = 1, nb
            q => mat_of(rig%bodies(b), k)
            q = a33(:, :, b)
         end do
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
