!> Unit tests of parallel contact without MPI (dx_contact_strips, dx_contact's three stages,
!> dx_par_contact's pair groups): strips of equal slave-node count along the longest axis,
!> ordered along it; the results of three strips, computed separately and merged, added in
!> the serial order give the serial contact forces, row sums, resultants and step bound bit
!> for bit; the local pair of contact_rod_box condenses into its two end elements and the
!> automatic single surface of contact_rod_single_surface into none.
program test_par_contact
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_model, only: model_t
   use dx_model_input, only: model_input_t
   use dx_deck, only: read_deck_input
   use dx_model_build, only: build_model_data
   use dx_contact_build, only: build_contact
   use dx_explicit, only: init_state
   use dx_contact, only: contact_forces, contact_search_nodes, contact_assemble, contact_dt, &
                         contact_vmax, contact_prepare
   use dx_contact_types, only: contact_pass_t
   use dx_contact_strips, only: strip_of
   use dx_sort, only: sort_index
   use dx_strings, only: str
   use dx_par_contact, only: contact_groups
   use dx_assert, only: check, check_close, assert_summary
   implicit none

   call test_strips()
   call test_strip_assembly()
   call test_groups()
   call assert_summary()

contains

   subroutine load(deck, model)
      character(*), intent(in) :: deck
      type(model_t), intent(out) :: model
      type(model_input_t) :: inp
      type(error_t), allocatable :: err
      call read_deck_input(deck, inp, err)
      if (allocated(err)) error stop 'cannot read the deck'
      model%deck_file = deck
      call build_model_data(inp, model, err)
      if (allocated(err)) error stop 'cannot build the model'
      call build_contact(inp, model, err)
      if (allocated(err)) error stop 'cannot build the contact'
   end subroutine load

   !> 1000 slave nodes in a 10 x 1 x 2 box (a fixed pseudo-random sequence): axis 1; strip
   !> sizes floor/ceil(n/NS) (here 1000/3: 333 or 334), every node of strip s at or below
   !> every node of strip s+1 along the axis; the same call gives the same strips.
   subroutine test_strips()
      type(contact_pass_t) :: p
      real(wp), allocatable :: x(:, :)
      integer, allocatable :: s1(:), s2(:)
      integer :: i, ns, s, n, k
      integer, parameter :: NSS(12) = [1, 2, 3, 4, 5, 6, 7, 16, 64, 999, 1000, 1500]
      logical :: ordered
      real(wp) :: r
      n = 1000
      allocate(x(3, n))
      r = 0.5_wp
      do i = 1, n
         r = mod(r*7919.0_wp + 0.123456789_wp, 1.0_wp); x(1, i) = 10.0_wp*r
         r = mod(r*7919.0_wp + 0.123456789_wp, 1.0_wp); x(2, i) = r
         r = mod(r*7919.0_wp + 0.123456789_wp, 1.0_wp); x(3, i) = 2.0_wp*r
      end do
      x(1, 10) = x(1, 11)         ! a tie: ordered by slave index
      p%nnode = n
      p%node = [(i, i = 1, n)]
      do ns = 1, 4
         call strip_of(p, x, ns, s1)
         call strip_of(p, x, ns, s2)
         call check(p%strip_axis == 1, 'strips: longest axis (x) with NS = '//char(48 + ns))
         call check(all(s1 == s2), 'strips: reproducible, NS = '//char(48 + ns))
         ordered = .true.
         do s = 0, ns - 1
            call check(count(s1 == s) == n/ns .or. count(s1 == s) == n/ns + 1, &
                       'strips: floor/ceil(n/NS) nodes in strip '//char(48 + s)//' of '// &
                       char(48 + ns))
            if (s < ns - 1) ordered = ordered .and. maxval(x(1, :), mask=s1 == s) <= &
                                                    minval(x(1, :), mask=s1 == s + 1)
         end do
         call check(ordered, 'strips: ordered along the axis, NS = '//char(48 + ns))
      end do
      call check(count(s1 == 0) + count(s1 == 1) + count(s1 == 2) + count(s1 == 3) == n, &
                 'strips: every node in one strip')
      ! many ties (x rounded to 20 values): the cuts (quickselect) equal those of a full sort
      ! by (coordinate, slave index), for NS = 1 .. 7, on the nodes in a shuffled slave order
      x(1, :) = real(nint(20.0_wp*x(1, :)/10.0_wp), wp)
      p%node = [(1 + mod(37*i, n), i = 0, n - 1)]
      deallocate(s2)
      do k = 1, 12
         ns = NSS(k)
         call strip_of(p, x, ns, s1)
         block
            integer, allocatable :: idx(:)
            real(wp), allocatable :: c(:)
            c = x(1, p%node)
            idx = [(i, i = 1, n)]
            call sort_index(idx, c)
            allocate(s2(n))
            do i = 1, n
               s2(idx(i)) = int((int(i - 1, 8)*int(ns, 8))/int(n, 8))
            end do
         end block
         call check(all(s1 == s2), 'strips: quickselect cuts = full sort, 20 tied values, NS = '// &
                    str(ns))
         deallocate(s2)
      end do
   end subroutine test_strips

   !> contact_rod_impact with the striker moved 0.02 mm into the target (8 slave nodes in
   !> contact over the two passes): the serial contact_forces against three strips computed
   !> on separate copies (nstrip = 3, istrip = 0, 1, 2), their results merged into one copy
   !> and added there (contact_assemble, contact_dt): fc, krow, the resultants, the number
   !> of nodes in contact and the contact step bound equal the serial ones bit for bit.
   subroutine test_strip_assembly()
      type(model_t) :: ms, m0, mr, mp
      real(wp) :: dts, dtp, w2, w2max, vmax
      logical :: due
      integer :: i, j, r, k, nd
      logical :: same
      call load('tests/regression/contact_rod_impact/deck.k', ms)
      call init_state(ms)
      do i = 1, ms%nn
         if (ms%x0(1, i) <= 100.005_wp) ms%x(1, i) = ms%x(1, i) + 0.02_wp
      end do
      m0 = ms
      dts = 1.0e-4_wp
      call contact_forces(ms, 0.0_wp, dts)
      call check(sum(ms%contact%iface(1)%pass(:)%nnode) > 0 .and. &
                 ms%contact%iface(1)%nactive == 8, 'strip assembly: 8 slave nodes in contact')
      ! penalty: k = SLSFAC K A^2/V = 0.1 x 70 GPa x 1 mm (E = 210, nu = 0), penetration
      ! 0.01 mm at 4 nodes, both passes: |f_slave| = 2 x 4 x 7 x 0.01 = 0.56 kN
      call check_close(abs(ms%contact%iface(1)%fslave(1)), 0.56_wp, 0.0_wp, 1.0e-9_wp, &
                       'strip assembly: serial slave resultant 0.56 kN (penalty x gap)')
      w2max = 0.0_wp
      mp = m0                     ! the state before any contact call
      m0%contact%nstrip = 3
      m0%contact%istrip = 0
      dtp = 1.0e-4_wp
      vmax = contact_vmax(m0%v, m0%contact%node)
      call contact_prepare(m0, 0.0_wp, vmax, due)
      call check(due, 'strip assembly: the first cycle sorts')
      call contact_search_nodes(m0, 0.0_wp, dtp, vmax, w2)
      do r = 0, 2
         mr = mp
         mr%contact%nstrip = 3
         mr%contact%istrip = r
         dtp = 1.0e-4_wp
         call contact_prepare(mr, 0.0_wp, vmax, due)
         call contact_search_nodes(mr, 0.0_wp, dtp, vmax, w2)
         w2max = max(w2max, w2)
         do j = 1, size(mr%contact%iface(1)%pass)
            associate (pr => mr%contact%iface(1)%pass(j), p0 => m0%contact%iface(1)%pass(j))
               call check(count(pr%mine) >= pr%nnode/3, 'strip assembly: strip holds n/3')
               do k = 1, pr%nnode
                  if (pr%mine(k)) then
                     p0%rint(:, k) = pr%rint(:, k)
                     p0%rval(:, k) = pr%rval(:, k)
                  end if
               end do
            end associate
         end do
      end do
      m0%f = 0.0_wp
      call contact_assemble(m0, w2max, .false.)
      dtp = 1.0e-4_wp
      call contact_dt(m0%contact, w2max, dtp)
      same = .true.
      do i = 1, size(ms%contact%node)
         nd = ms%contact%node(i)
         same = same .and. all(ms%contact%fc(:, nd) == m0%contact%fc(:, nd)) .and. &
                ms%contact%krow(nd) == m0%contact%krow(nd)
      end do
      call check(same, 'strip assembly: fc and krow bitwise serial at every contact node')
      call check(all(ms%contact%iface(1)%fslave == m0%contact%iface(1)%fslave) .and. &
                 all(ms%contact%iface(1)%fmaster == m0%contact%iface(1)%fmaster), &
                 'strip assembly: resultants bitwise serial')
      call check(ms%contact%iface(1)%nactive == m0%contact%iface(1)%nactive, &
                 'strip assembly: nodes in contact')
      call check(dts == dtp, 'strip assembly: contact step bound bitwise serial')
      call check(dts < 1.0e-4_wp, 'strip assembly: the contact bound lowers the step')
   end subroutine test_strip_assembly

   !> contact_rod_box: one local pair (SURFACE_TO_SURFACE restricted to the rod ends by
   !> boxes) -> one group of 2 elements, the striker's last (label 50) and the target's
   !> first (label 51); contact_rod_single_surface (AUTOMATIC_SINGLE_SURFACE) -> none;
   !> taylor_simo (no contact) -> none.
   subroutine test_groups()
      type(model_t) :: m
      integer, allocatable :: gp(:), ge(:), gid(:)
      call load('tests/regression/contact_rod_box/deck.k', m)
      call contact_groups(m, gp, ge, gid)
      call check(size(gid) == 1 .and. size(gp) == 2, 'groups: rod_box has one local pair')
      if (size(ge) == 2) then
         call check(all(m%elem_label(ge) == [50, 51]), 'groups: rod_box pair = elements 50, 51')
      else
         call check(.false., 'groups: rod_box pair has 2 elements')
      end if
      call load('tests/regression/contact_rod_single_surface/deck.k', m)
      call contact_groups(m, gp, ge, gid)
      call check(size(gid) == 0 .and. all(gp == [1]), 'groups: single surface is no pair')
      call load('tests/regression/taylor_simo/deck.k', m)
      call contact_groups(m, gp, ge, gid)
      call check(size(gid) == 0, 'groups: no contact, no group')
   end subroutine test_groups
end program test_par_contact
