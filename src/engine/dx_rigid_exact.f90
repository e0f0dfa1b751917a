!> The rigid-body stage with exact sums (dx_repro_sum), serial and MPI alike. A body's
!> resultant force, torque about its centre (r x f plus the nodal moments), nodal mass and
!> first moment are sums over its nodes: each rank adds the terms of the body nodes it owns
!> (dx_rigid_solver rigid_node_terms, the serial code), one int64 MPI_Allreduce per cycle
!> gives every rank the exact sums, and every rank advances every body from them with the
!> serial code (rigid_body_advance: the DLM rotation integrator of Dullweber, Leimkuhler &
!> McLachlan 1997, J Chem Phys 107:5840), so the bodies' states are the same bits on every
!> rank and in the serial run, for any NP, and no node's x, f or v is gathered. Each rank
!> then moves the body nodes it holds (owned and shared, rigid_node_motion: the same
!> secant velocity on every holder). The nodal kinetic energy and momentum the body's
!> replace are kept as this cycle's exact sums of the owned nodes (racc, negated), which the
!> energy event adds to its own sums (dx_energy_exact) before its one reduction.
module dx_rigid_exact
   use dx_kinds, only: wp
   use dx_model, only: model_t
   use dx_rigid_types, only: rigid_system_t
   use dx_rigid_solver, only: rigid_begin, rigid_node_terms, rigid_body_advance, &
                              rigid_node_motion
   use dx_repro_sum, only: rsum_t, rs_init, rs_add, rs_value, rs_reduce
   implicit none
   private
   public :: rigid_map_t, rigid_map_serial, rigid_exact_step

   integer, parameter :: RB_NS = 10     !< per body: force 3, torque 3, nodal mass, m r 3

   !> The body nodes this rank holds: body b's are node(ptr(b):ptr(b+1)-1) (local
   !> indices), pos their positions in the body's node list, own whether this rank owns
   !> them (adds their terms). racc: the cycle's rigid nodal terms (-m v(n-1/2).v(n+1/2),
   !> -m v(n+1/2)) of the owned nodes; acc: the bodies' sums of the cycle (kept: allocated
   !> once, cleared each cycle).
   type :: rigid_map_t
      integer, allocatable :: ptr(:), node(:), pos(:)
      logical, allocatable :: own(:)
      type(rsum_t) :: racc
      type(rsum_t) :: acc
   end type rigid_map_t

contains

   !> A serial run: every body node, owned.
   subroutine rigid_map_serial(map, rs)
      type(rigid_map_t), intent(inout) :: map
      type(rigid_system_t), intent(in) :: rs
      integer :: b, n, i
      if (allocated(map%ptr)) return
      allocate(map%ptr(size(rs%bodies) + 1))
      map%ptr(1) = 1
      do b = 1, size(rs%bodies)
         map%ptr(b + 1) = map%ptr(b) + size(rs%bodies(b)%nodes)
      end do
      n = map%ptr(size(rs%bodies) + 1) - 1
      allocate(map%node(n), map%pos(n), map%own(n))
      do b = 1, size(rs%bodies)
         do i = 1, size(rs%bodies(b)%nodes)
            map%node(map%ptr(b) + i - 1) = rs%bodies(b)%nodes(i)
            map%pos(map%ptr(b) + i - 1) = i
         end do
      end do
      map%own = .true.
   end subroutine rigid_map_serial

   !> The rigid stage of the cycle (in place of rigid_step): model%rigid advanced, the held
   !> body nodes moved; ke_corr, p_corr the plain local corrections (the cycle's kinetic
   !> energy guard), ke_body, p_body the bodies' own, map%racc the owned nodes' terms.
   subroutine rigid_exact_step(map, model, t, dt, dtavg, vold)
      type(rigid_map_t), intent(inout) :: map
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: t, dt, dtavg, vold(:, :)
      real(wp) :: grav(3), tf(3), tq(3), tm(3), m, mr(3), s(RB_NS), ke, p(3), ke_n
      integer :: b, j, c0, d, nb
      logical :: body_loads
      associate (rs => model%rigid, acc => map%acc)
         nb = size(rs%bodies)
         call rs_init(acc, RB_NS*nb)
         do b = 1, nb
            c0 = RB_NS*(b - 1)
            do j = map%ptr(b), map%ptr(b + 1) - 1
               if (.not. map%own(j)) cycle
               call rigid_node_terms(rs%bodies(b), model, map%node(j), tf, tq, tm, m, mr)
               do d = 1, 3
                  call rs_add(acc, c0 + d, tf(d))
                  call rs_add(acc, c0 + 3 + d, tq(d))
                  call rs_add(acc, c0 + 3 + d, tm(d))
                  call rs_add(acc, c0 + 7 + d, mr(d))
               end do
               call rs_add(acc, c0 + 7, m)
            end do
         end do
         call rs_reduce(acc)               ! over the ranks (collective; serial: no-op)
         call rigid_begin(rs, model, t, grav, body_loads)
         call rs_init(map%racc, 4)
         do b = 1, nb
            c0 = RB_NS*(b - 1)
            do d = 1, RB_NS
               s(d) = rs_value(acc, c0 + d)
            end do
            call rigid_body_advance(rs, rs%bodies(b), model, t, dt, dtavg, s(1:3), s(4:6), &
                                    s(7), s(8:10), grav, body_loads)
            ke_n = 0.0_wp
            do j = map%ptr(b), map%ptr(b + 1) - 1
               call rigid_node_motion(rs%bodies(b), model, map%pos(j), map%node(j), dt, vold, &
                                      ke, p)
               if (.not. map%own(j)) cycle
               ke_n = ke_n + ke
               rs%p_corr = rs%p_corr - p
               call rs_add(map%racc, 1, -ke)
               do d = 1, 3
                  call rs_add(map%racc, 1 + d, -p(d))
               end do
            end do
            rs%ke_corr = rs%ke_corr - 0.5_wp*ke_n
         end do
      end associate
   end subroutine rigid_exact_step
end module dx_rigid_exact
