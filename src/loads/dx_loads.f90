!> External loads evaluated once per cycle: *LOAD_NODE_POINT (force along a global axis, or
!> a moment about one on a node with rotations: DOF 5-7),
!> *LOAD_BODY_X/Y/Z (base acceleration, dx_load_body) and
!> *LOAD_SEGMENT(_SET) pressure on 3/4-node segments of the current geometry. A positive
!> pressure acts against the segment normal given by the right-hand rule on n1..n4
!> (LS-DYNA convention). Nodal shares: area vector A = (d13 x d24)/2 split 1/4 per node for a
!> quadrilateral (exact for a flat segment under uniform pressure), (d12 x d13)/2 in thirds
!> for a triangle. A 2-node edge (N3 = 0) of a 2D deck (dx_quad2d): normal (dy, -dx) (outward
!> for an edge in its element's counter-clockwise order), the load against it: p L/2 per node
!> in plane strain (unit thickness), int N_I p r ds per radian in axisymmetry (x = r):
!> p L (2 r1 + r2)/6 and p L (r1 + 2 r2)/6 (exact for the linear edge). Such an edge is stored
!> as nodes (N1, N2, 0, 0) in plane strain and (N1, N2, 0, -1) in axisymmetry (dx_build_loads).
module dx_loads
   use dx_kinds, only: wp
   use dx_vec3, only: cross
   use dx_model, only: model_t
   use dx_load_body, only: add_body_loads
   use dx_nonreflecting, only: add_nonreflecting
   use dx_edge_pressure, only: add_edge_pressures, deposit_energy
   implicit none
   private
   public :: add_external_loads, has_external_loads, load_rows, add_nonreflecting, &
             add_edge_pressures, deposit_energy   ! (the last three re-exported for the explicit loop)
contains

   !> Rows of the external-load array: 3 (forces), 6 when a *LOAD_NODE is a moment (DOF 5-7
   !> of LS-DYNA: rows 4-6 hold the moments about x, y, z; a deck without pays nothing).
   pure integer function load_rows(model)
      type(model_t), intent(in) :: model
      load_rows = 3
      if (allocated(model%node_loads)) then
         if (any(model%node_loads(:)%dof >= 5)) load_rows = 6
      end if
   end function load_rows

   !> .true. when the deck defines any external load (so the solver skips the pass otherwise)
   !> or a non-reflecting boundary (its dashpot forces ride in fext: dx_nonreflecting).
   pure logical function has_external_loads(model)
      type(model_t), intent(in) :: model
      has_external_loads = .false.
      if (allocated(model%node_loads)) has_external_loads = size(model%node_loads) > 0
      if (allocated(model%seg_loads)) has_external_loads = has_external_loads .or. &
                                                            size(model%seg_loads) > 0
      if (allocated(model%body_loads)) has_external_loads = has_external_loads .or. &
                                                             size(model%body_loads) > 0
      if (allocated(model%nr_node)) has_external_loads = .true.   ! dx_nonreflecting
      if (allocated(model%edge_pressures)) has_external_loads = .true.   ! dx_edge_pressure
   end function has_external_loads

   !> Add the external forces at time t to fext(3,nn) (zeroed by the caller); with 6 rows
   !> (load_rows) the nodal moments (DOF 5, 6, 7) into rows 4-6.
   subroutine add_external_loads(model, t, fext)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: t
      real(wp), intent(inout) :: fext(:, :)
      integer :: k, nd, n1, n2, n3, n4
      real(wp) :: val, p, d1(3), d2(3), area(3), w1, w2
      if (allocated(model%body_loads)) call add_body_loads(model%body_loads, model%curves, &
                                                           model%mass, t, fext)
      if (allocated(model%node_loads)) then
         do k = 1, size(model%node_loads)
            associate (ld => model%node_loads(k))
               val = ld%sf*model%curves(ld%curve)%eval(t)
               nd = ld%node
               if (ld%dof >= 1 .and. ld%dof <= 3) fext(ld%dof, nd) = fext(ld%dof, nd) + val
               if (ld%dof >= 5 .and. ld%dof <= 7 .and. size(fext, 1) >= 6) &
                  fext(ld%dof - 1, nd) = fext(ld%dof - 1, nd) + val
            end associate
         end do
      end if
      if (allocated(model%seg_loads)) then
         do k = 1, size(model%seg_loads)
            associate (ls => model%seg_loads(k))
               if (t < ls%at) cycle
               p = ls%sf*model%curves(ls%curve)%eval(t - ls%at)
               if (p == 0.0_wp) cycle
               n1 = ls%nodes(1); n2 = ls%nodes(2); n3 = ls%nodes(3); n4 = ls%nodes(4)
               if (n3 == 0) then          ! a 2-node edge of a 2D deck (n4 = -1: axisymmetric)
                  d1 = model%x(:, n2) - model%x(:, n1)
                  area = [d1(2), -d1(1), 0.0_wp]
                  w1 = 0.5_wp; w2 = 0.5_wp
                  if (n4 < 0) then
                     w1 = (2.0_wp*model%x(1, n1) + model%x(1, n2))/6.0_wp
                     w2 = (model%x(1, n1) + 2.0_wp*model%x(1, n2))/6.0_wp
                  end if
                  fext(1:3, n1) = fext(1:3, n1) - w1*p*area
                  fext(1:3, n2) = fext(1:3, n2) - w2*p*area
               else if (n4 == 0 .or. n4 == n3) then
                  d1 = model%x(:, n2) - model%x(:, n1)
                  d2 = model%x(:, n3) - model%x(:, n1)
                  area = 0.5_wp*cross(d1, d2)
                  fext(1:3, n1) = fext(1:3, n1) - p*area/3.0_wp
                  fext(1:3, n2) = fext(1:3, n2) - p*area/3.0_wp
                  fext(1:3, n3) = fext(1:3, n3) - p*area/3.0_wp
               else
                  d1 = model%x(:, n3) - model%x(:, n1)
                  d2 = model%x(:, n4) - model%x(:, n2)
                  area = 0.5_wp*cross(d1, d2)
                  fext(1:3, n1) = fext(1:3, n1) - 0.25_wp*p*area
                  fext(1:3, n2) = fext(1:3, n2) - 0.25_wp*p*area
                  fext(1:3, n3) = fext(1:3, n3) - 0.25_wp*p*area
                  fext(1:3, n4) = fext(1:3, n4) - 0.25_wp*p*area
               end if
            end associate
         end do
      end if
   end subroutine add_external_loads

end module dx_loads
