!> The 2D contact (dx_contact2d: *CONTACT_2D_AUTOMATIC_..) in an MPI run, replicated: every
!> rank holds the whole contact-node table (the contact nodes' global ids ascending, their
!> x, v and masses, the forces) and runs the serial brute-force pass on it, so each rank
!> computes the serial run's forces, contact step and work bit for bit (the pass visits
!> interfaces, passes, slave nodes and edges in the serial order; the compact numbering
!> keeps the serial node order, so the work sum over nodes is the serial one).
!>  - Set-up: the rank model's contact2d (a copy of the global one) is renumbered to the
!>    table (1..nc); a fixed gather plan of the owned contact nodes (by global id).
!>  - Contact stage: x(n), v(n-1/2) and the mass of every contact node from its owner (one
!>    MPI_Allgatherv of 5 numbers per node), then contact2d_forces on the table on every rank.
!>  - Exchange stage: each rank adds the contact forces at the contact nodes it holds after
!>    the shared-node sum (f = element sum + contact force, the serial order at every node).
!>  - Energy: the contact work is replicated, so the explicit loop's model%contact2d%work is
!>    the serial value on every rank (added once, not summed over the ranks).
!>  - Restart: each rank's dump part holds the (identical) table state through the serial
!>    writer; a serial dump read into the global model is mapped onto the table.
!> The serial algorithm: Hallquist, Goudreau & Benson 1985, CMAME 51:107-137; replicated
!> contact of a small interface after ParaDyn's global contact option (Hoover et al., LLNL
!> Engineering Thrust Area Report FY97, article 4 of shared/seed). Cost: O(contact nodes)
!> numbers per cycle on every rank and the whole search on every rank (no speed-up of the
!> contact; interfaces of a few thousand edges).
module dx_par_contact2d
   use dx_kinds, only: wp
   use dx_model, only: model_t
   use dx_contact2d, only: contact2d_forces
   use dx_par_plan, only: gather_plan_t, par_gather_setup, par_gather_values
   implicit none
   private
   public :: par_contact2d_t, par_contact2d_setup, par_contact2d_forces, par_contact2d_add, &
             par_contact2d_from_global

   !> The replicated 2D contact of a rank (a component of mpi_domain_t).
   type :: par_contact2d_t
      logical :: on = .false.
      integer, allocatable :: gid(:)        !< (nc) global ids of the contact nodes, ascending
      type(gather_plan_t) :: plan           !< the owned contact nodes, by global id
      integer, allocatable :: c_own(:)      !< local index of each owned contact node
      integer, allocatable :: kpos(:)       !< table position of each of plan%keys
      integer, allocatable :: l_loc(:)      !< held contact nodes: local index
      integer, allocatable :: l_pos(:)      !<   and table position
      real(wp), allocatable :: x(:, :)      !< (2, nc) x(n)
      real(wp), allocatable :: v(:, :)      !< (2, nc) v(n-1/2)
      real(wp), allocatable :: mass(:)      !< (nc)
      real(wp), allocatable :: f(:, :)      !< (2, nc) scratch (the forces are in contact2d%fc)
   end type par_contact2d_t

contains

   !> Start of an MPI run with 2D contact: model is the rank's sub-model (local nodes
   !> 1..nloc, global ids node_global, owned(i) if this rank owns local node i) with the
   !> global model's contact2d, renumbered here to the table.
   subroutine par_contact2d_setup(pc, model, node_global, owned)
      type(par_contact2d_t), intent(inout) :: pc
      type(model_t), intent(inout) :: model
      integer, intent(in) :: node_global(:)
      logical, intent(in) :: owned(:)
      logical, allocatable :: isc(:)
      integer, allocatable :: cpos(:)
      integer :: i, p, ng, nc, j
      if (.not. allocated(model%contact2d)) return
      associate (c => model%contact2d)
         ng = 0
         do i = 1, size(c%iface)
            do p = 1, 2
               ng = max(ng, max(0, maxval(c%iface(i)%pass(p)%node)), &
                        max(0, maxval(c%iface(i)%pass(p)%edge)))
            end do
         end do
         ng = max(ng, max(0, maxval(node_global)))
         allocate(isc(ng), cpos(ng))
         isc = .false.
         do i = 1, size(c%iface)
            do p = 1, 2
               isc(c%iface(i)%pass(p)%node) = .true.
               isc(reshape(c%iface(i)%pass(p)%edge, [size(c%iface(i)%pass(p)%edge)])) = .true.
            end do
         end do
         pc%gid = pack([(i, i = 1, ng)], isc)
         nc = size(pc%gid)
         cpos = 0
         cpos(pc%gid) = [(i, i = 1, nc)]
         do i = 1, size(c%iface)
            do p = 1, 2
               associate (ps => c%iface(i)%pass(p))
                  ps%node = cpos(ps%node)
                  ps%edge = reshape(cpos(reshape(ps%edge, [size(ps%edge)])), shape(ps%edge))
                  if (allocated(ps%own)) then   ! (element nodes off the surface: 0, never a slave)
                     do j = 1, size(ps%own, 2)
                        where (ps%own(:, j) >= 1 .and. ps%own(:, j) <= ng)
                           ps%own(:, j) = cpos(min(max(ps%own(:, j), 1), ng))
                        elsewhere
                           ps%own(:, j) = 0
                        end where
                     end do
                  end if
               end associate
            end do
         end do
         ! the table's state from cycle 0 (fold = 0: no work term until a force; the serial
         ! run's first v is never weighed), so a dump part always holds it
         if (allocated(c%fc)) deallocate(c%fc)
         if (allocated(c%fold)) deallocate(c%fold)
         if (allocated(c%vold)) deallocate(c%vold)
         allocate(c%fc(2, nc), c%fold(2, nc), c%vold(2, nc))
         c%fc = 0.0_wp
         c%fold = 0.0_wp
         c%vold = 0.0_wp
      end associate
      pc%l_loc = pack([(i, i = 1, size(node_global))], isc(node_global))
      pc%l_pos = cpos(node_global(pc%l_loc))
      pc%c_own = pack(pc%l_loc, owned(pc%l_loc))
      call par_gather_setup(pc%plan, node_global(pc%c_own))
      pc%kpos = cpos(pc%plan%keys)
      allocate(pc%x(2, nc), pc%v(2, nc), pc%mass(nc), pc%f(2, nc))
      pc%x = 0.0_wp
      pc%v = 0.0_wp
      pc%mass = 0.0_wp
      pc%f = 0.0_wp
      pc%on = .true.
   end subroutine par_contact2d_setup

   !> Contact stage: the table's x(n), v(n-1/2) and masses from the owners, then the serial
   !> pass on every rank (forces into model%contact2d%fc, the contact step into dtcrit).
   subroutine par_contact2d_forces(pc, model, dt_old, dtcrit)
      type(par_contact2d_t), intent(inout) :: pc
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: dtcrit
      real(wp), allocatable :: vals(:, :), gv(:, :)
      integer :: i, l
      allocate(vals(5, size(pc%c_own)), gv(5, size(pc%kpos)))
      do i = 1, size(pc%c_own)
         l = pc%c_own(i)
         vals(1:2, i) = model%x(1:2, l)
         vals(3:4, i) = model%v(1:2, l)
         vals(5, i) = model%mass(l)
      end do
      call par_gather_values(pc%plan, vals, gv)
      do i = 1, size(pc%kpos)
         pc%x(:, pc%kpos(i)) = gv(1:2, i)
         pc%v(:, pc%kpos(i)) = gv(3:4, i)
         pc%mass(pc%kpos(i)) = gv(5, i)
      end do
      call contact2d_forces(model%contact2d, pc%x, pc%v, pc%mass, dt_old, model%ctrl%tssfac, &
                            pc%f, dtcrit)
   end subroutine par_contact2d_forces

   !> Exchange stage (after the shared-node sums): the contact forces at the held nodes.
   subroutine par_contact2d_add(pc, model)
      type(par_contact2d_t), intent(in) :: pc
      type(model_t), intent(inout) :: model
      integer :: i
      do i = 1, size(pc%l_loc)
         model%f(1:2, pc%l_loc(i)) = model%f(1:2, pc%l_loc(i)) + &
                                     model%contact2d%fc(:, pc%l_pos(i))
      end do
   end subroutine par_contact2d_add

   !> A serial dump continued under MPI was read into the global model g (serial
   !> numbering): its 2D contact state onto the table (then dropped from g).
   subroutine par_contact2d_from_global(pc, model, g)
      type(par_contact2d_t), intent(in) :: pc
      type(model_t), intent(inout) :: model
      type(model_t), pointer, intent(in) :: g
      if (.not. pc%on .or. .not. associated(g)) return
      if (.not. allocated(g%contact2d)) return
      if (.not. allocated(g%contact2d%fold)) return
      associate (c => model%contact2d, s => g%contact2d)
         c%fold = s%fold(:, pc%gid)
         c%vold = s%vold(:, pc%gid)
         c%fc = 0.0_wp
         c%dtold = s%dtold
         c%work = s%work
         c%dtsoft = s%dtsoft
         deallocate(s%fc, s%fold, s%vold)
      end associate
   end subroutine par_contact2d_from_global
end module dx_par_contact2d
