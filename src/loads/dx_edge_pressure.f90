!> The laser-damage loads of 2D decks (seed article 3: DYNA2D's table look-up of LASNEX
!> pressures, the Gaussian pulse, the energy deposited into a particle):
!> - *DYNX_PRESSURE_TABLE: p(r, t) bilinear in the data file's table (r the edge's midpoint
!>   radius x at t = 0; below the first radius the first column, beyond the last radius and
!>   outside the times zero: the table covers the loaded spot and the pulse).
!> - *DYNX_PRESSURE_PULSE: p = PMAX exp(-4 ln 2 ((t - T0)/FWHM)**2) cos**2 theta per edge.
!> Both act on the edges' t = 0 geometry, each node's share -w_I (dy, -dx) of the edge load
!> (dx_loads: L/2, or L (2 r1 + r2)/6, L (r1 + 2 r2)/6 per radian): a fixed spot under small
!> motion of the loaded surface (DYNA2D's follows the surface), so the force on a node is a
!> function of t alone, formed node by node after the shared-node exchange on every MPI rank
!> holding the node, with the same bits (as dx_nonreflecting); its work is external work.
!> - *DYNX_ENERGY_DEPOSITION: RATE (TSTART..TEND) into the part's elements' internal energy,
!>   shared by initial volume, before the element pass of t(n): each step deposits RATE times
!>   the overlap of [t(n-1), t(n)] with [TSTART, TEND], so the sum is exact; the total enters
!>   the energy balance beside the external work (run state wdep).
module dx_edge_pressure
   use dx_kinds, only: wp
   use dx_model, only: model_t, edge_pressure_t
   implicit none
   private
   public :: add_edge_pressures, deposit_energy, table_pressure

contains

   !> p(r, t) of a *DYNX_PRESSURE_TABLE (see the module header)
   pure real(wp) function table_pressure(ep, r, t) result(p)
      type(edge_pressure_t), intent(in) :: ep
      real(wp), intent(in) :: r, t
      integer :: i, j, nr, nt
      real(wp) :: a, b
      p = 0.0_wp
      nr = size(ep%r); nt = size(ep%t)
      if (t < ep%t(1) .or. t > ep%t(nt) .or. r > ep%r(nr)) return
      j = 1
      do while (j < nt - 1 .and. t > ep%t(j + 1))
         j = j + 1
      end do
      b = (t - ep%t(j))/(ep%t(j + 1) - ep%t(j))
      if (nr == 1 .or. r <= ep%r(1)) then
         p = (1.0_wp - b)*ep%p(1, j) + b*ep%p(1, j + 1)
         return
      end if
      i = 1
      do while (i < nr - 1 .and. r > ep%r(i + 1))
         i = i + 1
      end do
      a = (r - ep%r(i))/(ep%r(i + 1) - ep%r(i))
      p = (1.0_wp - b)*((1.0_wp - a)*ep%p(i, j) + a*ep%p(i + 1, j)) + &
          b*((1.0_wp - a)*ep%p(i, j + 1) + a*ep%p(i + 1, j + 1))
   end function table_pressure

   !> fext(1:2, :) += the edge pressures' nodal forces at time t
   subroutine add_edge_pressures(model, t, fext)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: t
      real(wp), intent(inout) :: fext(:, :)
      real(wp), allocatable :: pe(:)
      real(wp) :: g
      integer :: i, k
      if (.not. allocated(model%edge_pressures)) return
      do i = 1, size(model%edge_pressures)
         associate (ep => model%edge_pressures(i))
            if (size(ep%node) == 0) cycle
            allocate(pe(size(ep%re)))
            if (ep%kind == 1) then
               do k = 1, size(pe)
                  pe(k) = table_pressure(ep, ep%re(k), t)
               end do
            else
               g = ep%pmax*exp(-4.0_wp*log(2.0_wp)*((t - ep%t0)/ep%fwhm)**2)
               pe = g*ep%ce
            end if
            do k = 1, size(ep%node)
               fext(1:2, ep%node(k)) = fext(1:2, ep%node(k)) + pe(ep%edge(k))*ep%w(:, k)
            end do
            deallocate(pe)
         end associate
      end do
   end subroutine add_edge_pressures

   !> The deposits over [t - dt, t] into the elements' internal energy; wdep += their sum
   subroutine deposit_energy(model, t, dt, wdep)
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: t, dt
      real(wp), intent(inout) :: wdep
      real(wp) :: de
      integer :: i, b
      if (.not. allocated(model%deposits)) return
      do i = 1, size(model%deposits)
         associate (dp => model%deposits(i))
            de = dp%rate*max(0.0_wp, min(t, dp%t2) - max(t - dt, dp%t1))
            if (de == 0.0_wp) cycle
            wdep = wdep + de
            do b = 1, size(model%blocks)
               associate (blk => model%blocks(b))
                  if (blk%ipart /= dp%ipart) cycle
                  blk%eint(1:blk%nel) = blk%eint(1:blk%nel) + de*(blk%vol0(1:blk%nel)/dp%vpart)
               end associate
            end do
         end associate
      end do
   end subroutine deposit_energy
end module dx_edge_pressure
