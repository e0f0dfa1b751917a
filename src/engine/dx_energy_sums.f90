!> The global sums of the explicit loop (kinetic energy, element energies, constraint work,
!> momentum, energy ratio), each in one procedure. The serial loop calls them on its model;
!> the MPI engine (src/parallel/dx_par_engine.f90) gathers the terms into the global model
!> and calls the very same procedures, so both add the same numbers in the same order with
!> the same machine code (no reassociation, no different FMA contraction): the parallel
!> glstat is the serial one bit for bit (docs/history.md, "Fixed-order sums").
!> Energy balance: Hallquist, DYNA3D User's Manual (UCRL-MA-107254), and Belytschko, Liu &
!> Moran 2000, section 6.2.3 (time-centred kinetic energy, work of constraint reactions).
module dx_energy_sums
   use dx_kinds, only: wp
   use dx_model, only: model_t, elem_block_t, energy_t, ES_WORK, WORK_PN, WORK_QBV
   implicit none
   private
   public :: initial_kinetic, kinetic_energy, element_energies, constraint_work, &
             constraint_terms, set_energy, constrained_nodes, energy_bits

contains

   !> 1/2 sum m v.v at the start.
   real(wp) function initial_kinetic(mass, v) result(e)
      real(wp), intent(in) :: mass(:), v(:, :)
      e = 0.5_wp*sum(mass*sum(v**2, dim=1))
   end function initial_kinetic

   !> Time-centred kinetic energy 1/2 sum_i m_i v_i(n-1/2).v_i(n+1/2), nodes 1..n in order.
   real(wp) function kinetic_energy(n, mass, vold, v) result(ke)
      integer, intent(in) :: n
      real(wp), intent(in) :: mass(:), vold(:, :), v(:, :)
      integer :: i
      ke = 0.0_wp
      do i = 1, n
         ke = ke + mass(i)*dot_product(vold(:, i), v(:, i))
      end do
      ke = 0.5_wp*ke
   end function kinetic_energy

   !> Internal and hourglass energy: per block sum, blocks in order.
   subroutine element_energies(blocks, eint, ehg, epend)
      type(elem_block_t), intent(in) :: blocks(:)
      real(wp), intent(out) :: eint, ehg
      real(wp), intent(out), optional :: epend  !< sum of the work still to be booked (ework 4 - 2)
      real(wp) :: pb
      integer :: b, i, w
      eint = 0.0_wp; ehg = 0.0_wp
      do b = 1, size(blocks)
         eint = eint + sum(blocks(b)%eint)
         ehg = ehg + sum(blocks(b)%ehg)
      end do
      if (present(epend)) then
         epend = 0.0_wp
         do b = 1, size(blocks)
            w = blocks(b)%esc(ES_WORK)
            if (w == 0) cycle
            pb = 0.0_wp
            do i = 1, blocks(b)%nel
               pb = pb + merge(0.0_wp, 1.0_wp, blocks(b)%failed(i))* &
                         (blocks(b)%es(i, w + WORK_PN) - blocks(b)%es(i, w + WORK_QBV))
            end do
            epend = epend + pb
         end do
      end if
   end subroutine element_energies

   !> Work of the constraint reactions over one step, added to wcon node by node (cnodes in
   !> ascending order; vfree(:, i) is node cnodes(i)'s velocity before the constraints).
   subroutine constraint_work(cnodes, mass, vfree, vold, v, dtavg, wcon, terms)
      integer, intent(in) :: cnodes(:)
      real(wp), intent(in) :: mass(:), vfree(:, :), vold(:, :), v(:, :), dtavg
      real(wp), intent(inout) :: wcon
      real(wp), intent(inout) :: terms(:)    !< work space, size(cnodes) at least
      integer :: i
      call constraint_terms(cnodes, mass, vfree, vold, v, dtavg, terms)
      do i = 1, size(cnodes)
         wcon = wcon + terms(i)
      end do
   end subroutine constraint_work

   !> The term of each constrained node in the constraint work, m (v(n+1/2) - vfree).du/dtavg
   !> with du = dtavg (v(n-1/2) + v(n+1/2))/2 (one node each: an MPI run computes the terms
   !> of its owned nodes with this code and adds the gathered terms in the serial order).
   subroutine constraint_terms(cnodes, mass, vfree, vold, v, dtavg, terms)
      integer, intent(in) :: cnodes(:)
      real(wp), intent(in) :: mass(:), vfree(:, :), vold(:, :), v(:, :), dtavg
      real(wp), intent(inout) :: terms(:)
      real(wp) :: du(3)
      integer :: i, nd
      do i = 1, size(cnodes)
         nd = cnodes(i)
         du = 0.5_wp*dtavg*(vold(:, nd) + v(:, nd))
         terms(i) = mass(nd)*dot_product(v(:, nd) - vfree(:, i), du)/dtavg
      end do
   end subroutine constraint_terms

   !> Store the energies and momentum of the current step in model%energy.
   subroutine set_energy(model, ke, eint, ehg, wext, erw)
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: ke, eint, ehg, wext, erw
      real(wp) :: den
      integer :: d
      model%energy%kinetic = ke
      model%energy%internal = eint
      model%energy%hourglass = ehg
      model%energy%external_work = wext
      model%energy%rigidwall = erw
      model%energy%total = ke + eint + ehg
      den = model%energy%initial + wext
      if (abs(den) > 0.0_wp) then
         model%energy%ratio = (model%energy%total + erw + model%energy%sliding)/den
      else
         model%energy%ratio = 1.0_wp
      end if
      do d = 1, 3
         model%energy%momentum(d) = sum(model%mass*model%v(d, :))
      end do
      if (allocated(model%rigid)) model%energy%momentum = model%energy%momentum + &
                                                         model%rigid%p_corr
   end subroutine set_energy

   !> Nodes with an SPC or prescribed motion (their reaction forces do work).
   subroutine constrained_nodes(model, nodes)
      type(model_t), intent(in) :: model
      integer, allocatable, intent(out) :: nodes(:)
      logical, allocatable :: mark(:)
      integer :: k
      allocate(mark(model%nn))
      mark = .false.
      if (allocated(model%spcs)) then
         do k = 1, size(model%spcs)
            if (any(model%spcs(k)%dof(1:3))) mark(model%spcs(k)%node) = .true.
         end do
      end if
      if (allocated(model%prescribed)) then
         do k = 1, size(model%prescribed)
            mark(model%prescribed(k)%node) = .true.
         end do
      end if
      nodes = pack([(k, k = 1, model%nn)], mark)
   end subroutine constrained_nodes

   !> The energies and momentum as IEEE-754 bit patterns (hex), for bitwise comparison of
   !> runs (glstat prints 11 digits, which hides differences in the last bits of a sum).
   function energy_bits(e) result(line)
      type(energy_t), intent(in) :: e
      character(:), allocatable :: line
      character(17) :: h
      real(wp) :: v(12)
      integer :: k
      v = [e%kinetic, e%internal, e%hourglass, e%external_work, e%rigidwall, e%sliding, &
           e%total, e%initial, e%ratio, e%momentum]
      line = 'dynx: energy bits (KE IE HG WEXT RW SI TOTAL E0 RATIO PX PY PZ):'
      do k = 1, size(v)
         write(h, '(1x,z16.16)') transfer(v(k), 0_8)
         line = line//h
      end do
   end function energy_bits
end module dx_energy_sums
