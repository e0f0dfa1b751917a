!> A rank's sub-model for the MPI engine (first piece of step 5; docs/history.md): its element
!> blocks are the pieces of the serial blocks it holds (serial block order, serial position
!> order), so the unchanged element kernels visit every interior node's contributions in the
!> serial order. A corner whose node is shared gets its own "slot" node (index nloc + slot)
!> in the block connectivity: the kernel's scatter then writes that single contribution into
!> f(:, nloc + slot) (0 - c, exactly -c), and par_shared_sum adds all ranks' slots of a node
!> in serial key order (scatter_keys: the serial loop `do k = 1, nen; do i = 1, nel` per
!> block) - bit for bit the serial sum, with no change to the kernels. The nodal mass is
!> scattered element-major (`do i; do k` in init_state), so it has its own keys and plan;
!> so are the shell kernel's forces and moments (family_t%scatter_em), and the rotary
!> inertia (par_exchange_mass on it). Moments use the force plan.
!> Follows the fixed-order idea of OpenRadioss /PARITH/ON and ParaDyn's single shared-node
!> exchange per cycle (LLNL Engineering Thrust Area Report FY97, article 4 of shared/seed).
module dx_par_model
   use dx_kinds, only: wp, nv_chunk
   use dx_model, only: model_t, elem_block_t, MAX_NEN, family_t, element_family
   use dx_partition, only: rank_part_t
   use dx_par_plan, only: shared_sum_t, par_shared_setup, par_shared_sum, par_shared_post, &
                          par_shared_finish, par_shared_drop
   implicit none
   private
   public :: par_model_t, par_model_build, par_fill_slots, par_exchange_forces, &
             par_exchange_mass, par_exchange_post, par_exchange_drop

   type :: par_model_t
      integer :: nloc = 0                       !< the rank's nodes (local 1..nloc)
      integer :: nslot = 0                      !< slot nodes nloc+1..nloc+nslot
      integer :: nshared = 0
      integer, allocatable :: node_global(:)    !< (nloc) global node index
      integer, allocatable :: slot_node(:)      !< (nslot) local node of each slot
      integer, allocatable :: shared_local(:)   !< (nshared) local node of each shared node
      type(elem_block_t), allocatable :: blocks(:)   !< pieces of the serial blocks
      integer, allocatable :: block_serial(:)   !< serial block of each piece
      type(shared_sum_t) :: force_plan, mass_plan
   end type par_model_t

contains

   !> Build rank rp%rank's sub-model from the (serial, built) model and its rank file.
   subroutine par_model_build(model, rp, pm)
      type(model_t), intent(in) :: model
      type(rank_part_t), intent(in) :: rp
      type(par_model_t), intent(out) :: pm
      integer, allocatable :: loc(:), snum(:), piece(:), c_node(:), c_fkey(:), &
                              c_mkey(:), nbr_snode(:)
      logical, allocatable :: here(:), shared(:)
      type(family_t) :: fam
      integer :: i, j, k, b, nb, n, slot, s
      pm%nloc = size(rp%nodes)
      pm%node_global = rp%nodes
      allocate(loc(model%nn), snum(model%nn), here(model%ne), shared(model%nn))
      loc = 0
      do i = 1, pm%nloc
         loc(rp%nodes(i)) = i
      end do
      here = .false.
      here(rp%elements) = .true.
      shared = .false.
      shared(rp%nbr_nodes) = .true.
      snum = 0
      s = 0
      do i = 1, pm%nloc
         if (shared(rp%nodes(i))) then
            s = s + 1
            snum(rp%nodes(i)) = s
         end if
      end do
      pm%nshared = s
      allocate(pm%shared_local(s))
      do i = 1, pm%nloc
         if (snum(rp%nodes(i)) > 0) pm%shared_local(snum(rp%nodes(i))) = i
      end do
      ! pieces of the serial blocks, in serial order
      nb = 0
      do b = 1, size(model%blocks)
         if (any(here(model%blocks(b)%elem))) nb = nb + 1
      end do
      allocate(pm%blocks(nb), pm%block_serial(nb))
      allocate(c_node(MAX_NEN*size(rp%elements)), c_fkey(MAX_NEN*size(rp%elements)), &
               c_mkey(MAX_NEN*size(rp%elements)), pm%slot_node(MAX_NEN*size(rp%elements)))
      nb = 0
      slot = 0
      do b = 1, size(model%blocks)
         associate (sb => model%blocks(b))
            piece = pack([(i, i = 1, sb%nel)], here(sb%elem))
            if (size(piece) == 0) cycle
            nb = nb + 1
            pm%block_serial(nb) = b
            fam = element_family(sb%etype)
            associate (pb => pm%blocks(nb))
               pb%ipart = sb%ipart
               pb%etype = sb%etype
               pb%nel = size(piece)
               pb%nip = sb%nip
               pb%nhv = sb%nhv
               pb%elem = sb%elem(piece)
               pb%sig = sb%sig(piece, :, :)
               pb%hv = sb%hv(piece, :, :)
               pb%vol0 = sb%vol0(piece)
               pb%relvol = sb%relvol(piece)
               pb%eint = sb%eint(piece)
               pb%ehg = sb%ehg(piece)
               pb%failed = sb%failed(piece)
               ! the family state (a restart reads it): every slot of the serial block
               if (allocated(sb%es)) pb%es = sb%es(piece, :)
               pb%esc = sb%esc; pb%esn = sb%esn
               allocate(pb%conn(size(sb%conn, 1), pb%nel))
               ! slots numbered corner-major as the force scatter visits them
               do k = 1, size(sb%conn, 1)
                  do j = 1, pb%nel
                     n = sb%conn(k, piece(j))
                     if (snum(n) > 0) then
                        slot = slot + 1
                        pb%conn(k, j) = pm%nloc + slot
                        pm%slot_node(slot) = loc(n)
                        c_node(slot) = snum(n)
                        ! force: the serial scatter order (dx_partition scatter_keys),
                        ! formed here for the rank's corners only
                        c_fkey(slot) = ((b - 1)*MAX_NEN + k - 1)*nv_chunk + piece(j)
                        ! mass: element-major serial order (block, position, corner)
                        c_mkey(slot) = ((b - 1)*nv_chunk + piece(j) - 1)*MAX_NEN + k
                        ! a family that scatters element-major (shells: forces and
                        ! moments) sums in that order; both keys span the same range
                        ! per block, so blocks of both kinds interleave in serial order
                        if (fam%scatter_em) c_fkey(slot) = c_mkey(slot)
                     else
                        pb%conn(k, j) = loc(n)
                     end if
                  end do
               end do
            end associate
         end associate
      end do
      pm%nslot = slot
      pm%slot_node = pm%slot_node(1:slot)
      nbr_snode = snum(rp%nbr_nodes)
      call par_shared_setup(pm%force_plan, pm%nshared, rp%nbr, rp%nbr_ptr, nbr_snode, &
                            c_node(1:slot), c_fkey(1:slot))
      call par_shared_setup(pm%mass_plan, pm%nshared, rp%nbr, rp%nbr_ptr, nbr_snode, &
                            c_node(1:slot), c_mkey(1:slot))
   end subroutine par_model_build

   !> Copy the shared nodes' state (x, v: (3, nloc + nslot)) into their slot nodes.
   subroutine par_fill_slots(pm, a)
      type(par_model_t), intent(in) :: pm
      real(wp), intent(inout) :: a(:, :)
      integer :: i
      do i = 1, pm%nslot
         a(:, pm%nloc + i) = a(:, pm%slot_node(i))
      end do
   end subroutine par_fill_slots

   !> After the element pass into f (3, nloc + nslot), zeroed before it: the one exchange;
   !> f at the shared nodes becomes the serial sum of all ranks' contributions. When the
   !> slots' values were posted already (par_exchange_post) only the wait and the sums.
   subroutine par_exchange_forces(pm, f)
      type(par_model_t), intent(inout) :: pm
      real(wp), intent(inout) :: f(:, :)
      if (.not. pm%force_plan%posted) &
         call par_shared_post(pm%force_plan, f(:, pm%nloc + 1:pm%nloc + pm%nslot))
      call par_shared_finish(pm%force_plan, f, pm%shared_local)
   end subroutine par_exchange_forces

   !> The slots of f are final (right after the element pass): their values sent now, the
   !> sums formed by the next par_exchange_forces (or discarded by par_exchange_drop).
   subroutine par_exchange_post(pm, f)
      type(par_model_t), intent(inout) :: pm
      real(wp), intent(in) :: f(:, :)
      call par_shared_post(pm%force_plan, f(:, pm%nloc + 1:pm%nloc + pm%nslot))
   end subroutine par_exchange_post

   subroutine par_exchange_drop(pm)
      type(par_model_t), intent(inout) :: pm
      call par_shared_drop(pm%force_plan)
   end subroutine par_exchange_drop

   !> The same for the lumped mass (nloc + nslot), scattered element-major.
   subroutine par_exchange_mass(pm, mass)
      type(par_model_t), intent(inout) :: pm
      real(wp), intent(inout) :: mass(:)
      real(wp), allocatable :: res(:, :)
      allocate(res(1, pm%nshared))
      call par_shared_sum(pm%mass_plan, reshape(mass(pm%nloc + 1:pm%nloc + pm%nslot), &
                          [1, pm%nslot]), res)
      mass(pm%shared_local) = res(1, :)
   end subroutine par_exchange_mass
end module dx_par_model
